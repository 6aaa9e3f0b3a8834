#include "run/time_checkpoint.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace fsi {
namespace {

// Text as doubles (one per byte): a solver's status words, kept with the state.
Eigen::VectorXd text_values(const std::string& text) {
  Eigen::VectorXd v(static_cast<long>(text.size()));
  for (std::size_t i = 0; i < text.size(); ++i) v[static_cast<long>(i)] = static_cast<unsigned char>(text[i]);
  return v;
}

std::string values_text(const Eigen::VectorXd& v) {
  std::string text;
  for (long i = 0; i < v.size(); ++i) text += static_cast<char>(static_cast<unsigned char>(v[i]));
  return text;
}

// A row's numbers in a fixed order, the probes' last.
constexpr long kRowFixed = 15;
Eigen::VectorXd row_values(const StructureRow& r) {
  Eigen::VectorXd v(kRowFixed + 2 * static_cast<long>(r.probes.size()));
  v.head(kRowFixed) << r.step, r.t, r.qp_iterations, r.active_nodes, r.max_u, r.kinetic, r.elastic, r.work,
      r.velocity.x(), r.velocity.y(), r.contact_force.x(), r.contact_force.y(), r.passes, r.fluid_force.x(),
      r.fluid_force.y();
  for (std::size_t i = 0; i < r.probes.size(); ++i) v.segment(kRowFixed + 2 * long(i), 2) = r.probes[i];
  return v;
}

StructureRow values_row(const Eigen::VectorXd& v) {
  StructureRow r;
  r.step = int(v[0]), r.t = v[1], r.qp_iterations = int(v[2]), r.active_nodes = int(v[3]), r.max_u = v[4];
  r.kinetic = v[5], r.elastic = v[6], r.work = v[7], r.velocity = Point(v[8], v[9]);
  r.contact_force = Point(v[10], v[11]), r.passes = int(v[12]), r.fluid_force = Point(v[13], v[14]);
  for (long i = kRowFixed; i + 1 < v.size(); i += 2) r.probes.emplace_back(v[i], v[i + 1]);
  return r;
}

}  // namespace

std::string case_fingerprint(const Case& c) {
  Case numbers = c;
  numbers.name.clear();
  numbers.output = OutputParams{};  // but the probes: history.csv's columns
  numbers.output.probes = c.output.probes, numbers.output.fluid_probes = c.output.fluid_probes;
  if (numbers.time) numbers.time->t_end = numbers.time->dt, numbers.time->output_every = 1, numbers.time->checkpoint_every = 0;
  return fnv1a_hex(to_toml(numbers));
}

Checkpoint new_checkpoint(const Case& c, const char* kind, int step, double t) {
  Checkpoint k;
  k.kind = kind;
  k.fingerprint = case_fingerprint(c);
  k.step = step;
  k.t = t;
  return k;
}

Checkpoint read_resume_checkpoint(const std::string& dir, const Case& c, const char* kind) {
  const std::string path = (std::filesystem::path(dir) / checkpoint_file_name()).string();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError("--resume " + dir + ": not a directory (--resume takes the output directory of a time run)");
  if (!std::filesystem::exists(path, ec))
    throw InputError("--resume " + dir + ": no " + checkpoint_file_name() +
                     " there (a time run writes one at its end, when stopped, and every time.checkpoint_every steps)");
  Checkpoint k = read_checkpoint(path);
  if (k.kind != kind)
    throw InputError(path + ": a checkpoint of a " + k.kind + " run, and " + c.source + " is a " + kind + " run");
  if (k.fingerprint != case_fingerprint(c))
    throw InputError(path + ": a checkpoint of another case than " + c.source +
                     " (only its name, output.* but the probes, time.t_end, time.output_every and time.checkpoint_every may differ)");
  if (!c.time || k.step > c.time->steps())
    throw InputError(path + ": its step " + std::to_string(k.step) + " (t = " + shortest(k.t) + " s) is past time.t_end = " +
                     shortest(c.time ? c.time->t_end : 0.0) + " s; allowed: time.t_end >= " + shortest(k.t));
  return k;
}

void put_newmark(Checkpoint& k, const NewmarkState& s) {
  k.put("newmark.u", s.u), k.put("newmark.v", s.v), k.put("newmark.a", s.a);
  const ContactSolution& c = s.contact;
  k.put("contact.u", c.u), k.put("contact.x", c.qp.x), k.put("contact.alpha", c.qp.alpha);
  std::vector<int> active(c.qp.active.begin(), c.qp.active.end());
  k.put_ints("contact.active", active);
  const KktResiduals& r = c.qp.kkt;
  k.put("contact.numbers", Eigen::VectorXd((Eigen::VectorXd(9) << c.qp.iterations, r.stationarity, r.feasibility,
                                            r.complementarity, r.dual_feasibility, c.newton.steps, c.newton.load_steps,
                                            c.newton.cuts, c.newton.residual).finished()));
  k.put("contact.newton_history", Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(c.newton.history.data(),
                                                                                    long(c.newton.history.size()))));
  k.put("contact.status", text_values(c.qp.status));
}

NewmarkState get_newmark(const Checkpoint& k, long dofs) {
  NewmarkState s;
  s.step = k.step, s.t = k.t;
  s.u = k.vector("newmark.u", dofs), s.v = k.vector("newmark.v", dofs), s.a = k.vector("newmark.a", dofs);
  ContactSolution& c = s.contact;
  c.u = k.vector("contact.u", dofs), c.qp.x = k.vector("contact.x"), c.qp.alpha = k.vector("contact.alpha");
  for (int a : k.ints("contact.active")) c.qp.active.push_back(a != 0);
  if (c.qp.active.size() != static_cast<std::size_t>(c.qp.alpha.size()))
    throw InputError(k.source + ": its contact rows disagree in number (a damaged checkpoint)");
  const Eigen::VectorXd& n = k.vector("contact.numbers", 9);
  c.qp.iterations = int(n[0]);
  c.qp.kkt = {n[1], n[2], n[3], n[4]};
  c.newton.steps = int(n[5]), c.newton.load_steps = int(n[6]), c.newton.cuts = int(n[7]), c.newton.residual = n[8];
  const Eigen::VectorXd& h = k.vector("contact.newton_history");
  c.newton.history.assign(h.data(), h.data() + h.size());
  c.qp.status = values_text(k.vector("contact.status"));
  return s;
}

void put_fluid(Checkpoint& k, const std::string& name, const FluidSolution& s) {
  k.put(name + ".v1", s.v1), k.put(name + ".v2", s.v2), k.put(name + ".p", s.p);
  k.put(name + ".bubble", Eigen::VectorXd(s.bubble.reshaped()));
}

FluidSolution get_fluid(const Checkpoint& k, const std::string& name, int vertices, int triangles) {
  FluidSolution s;
  s.v1 = k.vector(name + ".v1", vertices), s.v2 = k.vector(name + ".v2", vertices), s.p = k.vector(name + ".p", vertices);
  s.bubble = k.vector(name + ".bubble", 2L * triangles).reshaped(2, triangles);
  return s;
}

void put_near_region(Checkpoint& k, const NearRegionState& s) {
  if (s.mask.empty()) return;
  std::vector<int> near;
  for (std::size_t t = 0; t < s.mask.size(); ++t)
    if (s.mask[t]) near.push_back(static_cast<int>(t));
  k.put_ints("near_region.triangles", near);
  k.put("near_region.margin", s.margin);
}

NearRegionState get_near_region(const Checkpoint& k, int triangles) {
  NearRegionState s;
  if (!k.has("near_region.triangles")) return s;
  s.mask.assign(static_cast<std::size_t>(triangles), 0);
  for (int t : k.ints("near_region.triangles")) {
    if (t < 0 || t >= triangles)
      throw InputError(k.source + ": its fluid near region names triangle " + std::to_string(t) + " of " +
                       std::to_string(triangles));
    s.mask[static_cast<std::size_t>(t)] = 1;
  }
  s.margin = k.scalar("near_region.margin");
  return s;
}

void put_rows(Checkpoint& k, const StructureRow& initial, const std::vector<StructureRow>& rows) {
  const Eigen::VectorXd first = row_values(initial);
  Eigen::MatrixXd all(first.size(), 1 + static_cast<long>(rows.size()));
  all.col(0) = first;
  for (std::size_t i = 0; i < rows.size(); ++i) all.col(1 + long(i)) = row_values(rows[i]);
  k.put_matrix("history", all);
}

void get_rows(const Checkpoint& k, StructureRow& initial, std::vector<StructureRow>& rows) {
  const Eigen::MatrixXd all = k.matrix("history");
  if (all.cols() != k.step + 1 || all.rows() < kRowFixed || (all.rows() - kRowFixed) % 2)
    throw InputError(k.source + ": its history has " + std::to_string(all.cols()) + " rows for step " +
                     std::to_string(k.step) + " (a damaged checkpoint)");
  initial = values_row(all.col(0));
  rows.clear();
  for (long i = 1; i < all.cols(); ++i) rows.push_back(values_row(all.col(i)));
}

}  // namespace fsi
