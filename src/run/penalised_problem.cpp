#include "run/penalised_problem.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "fem/probes.hpp"
#include "io/atomic_file.hpp"
#include "io/figure.hpp"
#include "io/vtu.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_band.hpp"
#include "run/outputs/coupling_outputs.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "run/outputs/obstacle_forces.hpp"
#include "run/outputs/output_dir.hpp"

namespace fsi {
namespace {

// ‖v_h‖ over the fluid triangles where χ = 1 (the region the penalty acts on).
double velocity_l2_on_chi(const FluidField& field, const Mesh& fluid_mesh, const Eigen::VectorXd& chi) {
  Mesh region;
  region.vertices = fluid_mesh.vertices;
  for (int t = 0; t < fluid_mesh.num_triangles(); ++t)
    if (chi[t] >= 1.0) region.triangles.push_back(fluid_mesh.triangles[t]);
  return velocity_l2_over(field, region);
}

// ‖v_h‖ over the deformed structure and over χ = 1. The norms read the fields in the
// fluid triangles those meet only, which a solution exact near the structure holds;
// if the structure reaches beyond it, the solution is completed first. `failure`
// says why they are missing.
struct FluidNorms {
  double v = NAN, v_chi = NAN;
  std::string failure;
};

FluidNorms fluid_norms(FluidSetup& f, const Mesh& deformed) {
  FluidNorms n;
  if (!f.stokes->has_solution()) return n;
  const Eigen::VectorXd& chi = f.stokes->last_solution_chi();
  std::vector<int> read = triangles_meeting(*f.locator, deformed);
  for (int t = 0; t < f.mesh->num_triangles(); ++t)
    if (chi[t] >= 1.0) read.push_back(t);
  try {
    const FluidField field(*f.locator, f.stokes->solution(&read));
    n.v = velocity_l2_over(field, deformed);
    n.v_chi = velocity_l2_on_chi(field, *f.mesh, chi);
  } catch (const SolverFailure& e) {
    n.failure = e.what();
  }
  return n;
}

// Whether the structure can be meshed and set up while the box is meshed: both
// meshes from the generator (Gmsh runs in a forked child, which must not share the
// process with a second thread), and a box that does not depend on the structure
// (no band around its load-alone solution).
bool meshes_apart(const Case& c) {
  return c.structure.rectangle() && c.structure.mesher == "lattice" && c.fluid->mesh.empty() &&
         c.fluid->mesher == "lattice" && !band_needs_structure(c);
}

}  // namespace

void PenalisedProblem::set_up(PhaseTimes& times) {
  if (c_.output.png) fonts_ = std::async(std::launch::async | std::launch::deferred, load_figure_fonts);
  PhaseTimes structure_times;  // its own: PhaseTimes is not shared between threads
  const auto structure = [&] {
    s_stats_ = in_phase(structure_times, "mesh", [&] { return statistics(cache_.structure_mesh(c_)); });
    s_ = in_phase(structure_times, "structure", [&] { return &cache_.structure(c_); });
  };
  // The structure on a second core where it can (~5 ms at hS = 0.015 beside the
  // box's ~20 ms at hF = 0.01), its phases timed there: they overlap the box's.
  std::future<void> apart;
  if (meshes_apart(c_)) apart = std::async(std::launch::async | std::launch::deferred, structure);
  if (!apart.valid()) structure();
  try {
    band_ = in_phase(times, "mesh", [&] { return cache_.band(c_); });
    f_stats_ = in_phase(times, "mesh", [&] { return statistics(cache_.fluid_mesh(c_)); });
  } catch (...) {
    if (apart.valid()) apart.get();  // the structure's failure first, as if in turn
    throw;
  }
  if (apart.valid()) apart.get();
  for (const char* phase : {"mesh", "structure"}) times.add(phase, structure_times.get(phase));
  f_ = in_phase(times, "fluid", [&] { return &cache_.fluid(c_); });
}

FluidForce PenalisedProblem::fluid_force() const {
  const VectorField f = fluid_body_force(*c_.fluid);  // f_F∘φ in eq. (33)
  const ForceModel model = c_.coupling.force == "large" ? ForceModel::large : ForceModel::small;
  const double eps = f_->stokes->eps();  // the fluid's ε (a sweep's row sets it there): one owner
  if (s_->p2()) return FluidForce(*s_->p2(), c_.fluid->mu, eps, f, model);
  return FluidForce(s_->mesh(), c_.fluid->mu, eps, f, model, c_.coupling.force_sampling);
}

void PenalisedProblem::complete_fluid() {
  if (!(c_.output.png || c_.output.vtu || options_.keep_fields) || !f_->stokes->has_solution()) return;
  try {
    fluid_ = &f_->stokes->solution();
  } catch (const SolverFailure& e) {
    if (result_.failure.empty()) result_.failure = std::string("the fluid solve (far field) failed: ") + e.what();
  }
}

void PenalisedProblem::measure(RunResult& r) {
  const Eigen::VectorXd& u = result_.structure.u;
  deformed_ = displaced(s_->mesh(), component(u, 0), component(u, 1));
  const FluidNorms norms = fluid_norms(*f_, deformed_);
  const double max_u = max_displacement(u);
  if (result_.failure.empty() && !(std::isfinite(norms.v) && std::isfinite(norms.v_chi) && std::isfinite(max_u)))
    result_.failure = "the final state is not finite (|v| in the structure " + std::to_string(norms.v) +
                      ", max displacement " + std::to_string(max_u) + ")" +
                      (norms.failure.empty() ? "" : ": " + norms.failure);
  measure_final_state(r, f_stats_);
  r.measures.fluid_in_structure = RunMeasures::FluidInStructure{norms.v, norms.v / f_->stokes->eps(), norms.v_chi};
  // The velocity picture, drawn and encoded on a second thread from here: it is the
  // largest output (~35 ms at hF = 0.01), and it overlaps the summary and the other
  // files. The fluid is complete by now (complete_fluid), so the reads that follow
  // (the obstacle forces) leave it unchanged.
  if (!(c_.output.png && fluid_)) return;
  char note[256];
  std::snprintf(note, sizeof note, "eps = %g, omega = %g (%s), hF = %g, hS = %g;  %s", c_.coupling.eps,
                c_.coupling.omega, c_.coupling.scheme.c_str(), c_.fluid->h, c_.structure.h, picture_state().c_str());
  png_ = std::async(std::launch::async | std::launch::deferred,
                    [this, note = std::string(note), contact = contact_vertices(),
                     name = RunOutputs(c_.output.dir).path(picture_name())] {
                      return fluid_png(name, c_, *f_->mesh, *fluid_, deformed_, contact,
                                       c_.name + ": fluid velocity magnitude", note);
                    });
}

// summary.json's keys (SPEC §8, §9, §10).
void PenalisedProblem::summarise(RunResult& r) {
  const RunMeasures& m = r.measures;
  Json& j = r.summary;
  j = summary_header(c_, kind());
  j["mesh"] = {{"structure", to_json(m.structure_mesh)}, {"fluid", to_json(m.fluid_mesh)}};
  j["initial_state"] = options_.initial_displacement ? "given" : "rest";
  if (band_) {
    j["mesh"]["fluid"]["h_near"] = c_.fluid->h_near;
    j["mesh"]["fluid"]["band_box"] = *band_;
    j["mesh"]["fluid"]["band_warning"] =
        inside_band(deformed_, *band_, c_.fluid->h_near)
            ? Json(nullptr)
            : Json("the structure's final configuration leaves the band refined to fluid.h_near: widen fluid.band");
  }
  add_measures(j, m);
  add_structure_displacements(j, c_, *s_, result_);
  summarise_structure(j, m);
  if (c_.obstacles_given) j["obstacles"] = obstacle_forces_json(c_, *f_);  // the fluid's force on each (SPEC §10)
  if (!c_.output.fluid_probes.empty()) j["fluid_at"] = fluid_probes_json(c_, *f_);
  j["fluid"] = fluid_json(*f_->stokes);
  j["fluid"].update(flow_json(c_));
  r.report = report(m);
}

// The fields where they exist everywhere (none without fluid_), the structure's files,
// case.toml, and the velocity picture once it is drawn. The files themselves are
// written one at a time (an interrupted write removes its one temporary:
// common/interrupt.hpp).
void PenalisedProblem::write(RunOutputs& out) {
  bool fluid_vtu = false;
  if (c_.output.vtu && fluid_)
    fluid_vtu = out.write("fluid.vtu", [&](const std::string& p) {
      write_fluid_vtu(p, c_, *f_->mesh, *fluid_, f_->stokes->last_solution_chi());
    });
  write_structure(out, fluid_vtu);
  write_case_toml(out, c_);
  if (png_.valid()) out.write(picture_name(), [&](const std::string& p) { write_file_atomically(p, png_.get()); });
}

void PenalisedProblem::final_fields(FinalFields& out) const {
  if (s_) out.structure = structure_arrays_if_solved(*s_, result_.structure);
  if (fluid_) out.fluid = fluid_arrays(*f_->mesh, *fluid_, f_->stokes->last_solution_chi());
}

}  // namespace fsi
