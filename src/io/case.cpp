#include "io/case.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/input_file.hpp"
#include "common/launch.hpp"
#include "io/case_reader.hpp"
#include "io/case_section.hpp"
#include "io/output_path.hpp"

namespace fsi {
namespace case_detail {

bool Range::contains(double v) const {
  if (zero_or_magnitude) return v == 0 || (std::abs(v) >= lo && std::abs(v) <= hi);
  return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi);
}

std::string Range::text() const {
  if (zero_or_magnitude) return "0 or a magnitude in [" + shortest(lo) + ", " + shortest(hi) + "]";
  if (hi == inf) return lo == -inf ? "any finite number" : (lo_closed ? ">= " : "> ") + shortest(lo);
  if (lo == -inf) return (hi_closed ? "<= " : "< ") + shortest(hi);
  return std::string(lo_closed ? "[" : "(") + shortest(lo) + ", " + shortest(hi) + (hi_closed ? "]" : ")");
}

void fail(const Origin& origin, const std::string& key, const std::string& problem, const std::string& allowed) {
  throw InputError(origin.of(key) + ": " + key + " " + problem + (allowed.empty() ? "" : "; allowed: " + allowed));
}

void check_case(const Case& c, const Origin& origin);  // case_checks.cpp

}  // namespace case_detail

namespace {

using namespace case_detail;

}  // namespace

// "fixed" → 0; "layer" → 2 (ε ∝ h²); "h^p" → p for 0 < p <= 4; anything else: none.
std::optional<double> eps_rule_power(const std::string& rule) {
  if (rule == "fixed") return 0.0;
  if (rule == "layer") return 2.0;
  if (rule.size() < 3 || rule.compare(0, 2, "h^") != 0) return std::nullopt;
  double p = 0;
  const auto [end, ec] = std::from_chars(rule.data() + 2, rule.data() + rule.size(), p);
  if (ec != std::errc{} || end != rule.data() + rule.size() || !(p > 0 && p <= 4)) return std::nullopt;
  return p;
}

namespace {

[[noreturn]] void bad_override(const std::string& text) {
  throw InputError("--set " + text + ": expected section.key=value (for example coupling.omega=0.2)");
}

// "section.key=value" (or "key=value" for a top-level key such as name): the value
// parsed as TOML, or taken as a bare string.
void apply_override(toml::table& root, const std::string& text, Origin& origin) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) bad_override(text);
  const std::string path = text.substr(0, eq), value = text.substr(eq + 1);
  const auto dot = path.find('.');
  const std::string section = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  if ((dot != std::string::npos && (section.empty() || key.empty())) || key.find('.') != std::string::npos)
    bad_override(text);
  toml::table holder;
  try {
    holder = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    holder.insert_or_assign("v", value);  // a bare word such as aitken
  }
  toml::table* t = &root;
  if (!section.empty()) {
    if (!root.contains(section)) root.insert(section, toml::table{});
    t = root[section].as_table();
    if (!t) throw InputError("--set " + text + ": " + section + " is not a section");
  } else if (key != "name") {
    bad_override(text);
  }
  t->insert_or_assign(key, *holder.get("v"));
  origin.overridden.insert(path);
}

std::string resolve_path(const std::string& file, const std::string& case_path) {
  if (file.empty() || case_path.empty()) return file;
  const std::filesystem::path p(file);
  if (p.is_absolute()) return file;
  return (std::filesystem::path(case_path).parent_path() / p).lexically_normal().string();
}

// A name becomes a directory (out/<name>): letters, digits, '.', '_', '-', not
// starting with '.' (".." would write into the working directory) and short enough
// for a file name with room for what the sweep appends.
void check_name(const std::string& name, const Origin& origin) {
  const std::string allowed = "1 to 200 letters, digits, '.', '_', '-', not starting with '.'";
  if (name.empty() || name.size() > 200 || name[0] == '.' ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") != std::string::npos)
    fail(origin, "name", "= \"" + name.substr(0, 60) + (name.size() > 60 ? "..." : "") + "\" cannot name an output directory",
         allowed);
}

const std::set<std::string> kSections = {"structure", "obstacle", "obstacles", "fluid", "coupling", "contact", "output", "time", "name"};

// structure.shape and the files it names agree: one file, the one the shape reads.
void check_shape_files(const StructureParams& p, const Origin& origin) {
  const char* allowed = "shape = \"rectangle\" or \"none\" with neither file, \"mesh\" with structure.mesh, "
                        "\"geo\" with structure.geo";
  if (!p.mesh.empty() && !p.geo.empty())
    fail(origin, "structure.geo", "and structure.mesh are both given", allowed);
  if (p.shape == "rectangle" && !(p.mesh.empty() && p.geo.empty()))
    fail(origin, "structure.shape", "= \"rectangle\" is generated from L and H, but structure." +
                                        std::string(p.mesh.empty() ? "geo" : "mesh") + " is given", allowed);
  if (p.shape == "none" && !(p.mesh.empty() && p.geo.empty()))
    fail(origin, "structure.shape", "= \"none\" has no structure, but structure." +
                                        std::string(p.mesh.empty() ? "geo" : "mesh") + " is given", allowed);
  if (p.shape == "mesh" && p.mesh.empty())
    fail(origin, "structure.shape", "= \"mesh\" needs the file structure.mesh", allowed);
  if (p.shape == "geo" && p.geo.empty())
    fail(origin, "structure.shape", "= \"geo\" needs the script structure.geo", allowed);
}

// ν → 0.5 makes λ/μ = 2ν/(1 − 2ν) grow without bound and A_S singular in double
// precision: measured, the Cholesky factorisation failed at ν = 0.49999999999999
// (λ/μ = 3.5e13) and held at 0.499999999999 (5e11). λ/μ ≤ 1e8 keeps a margin of 5000.
constexpr double kMaxPoisson = 0.499999995;

void read_structure(const toml::table& root, const Origin& origin, const std::string& case_path, Case& c,
                    std::vector<std::string>* known) {
  Section s(section_table(root, "structure", origin), "structure", origin, known);
  auto& p = c.structure;
  p.extent_given = s.has("L") || s.has("H");
  p.L = s.number("L", p.L, kSize);
  p.H = s.number("H", p.H, kSize);
  p.E = s.number("E", p.E, kSize);
  p.nu = s.number("nu", p.nu, {0, kMaxPoisson, true, true});  // ν = 0: the bar impact (SPEC §12)
  p.f = s.vector2_or_expressions("f", p.f, p.f_expression, {0, 0, p.L, p.H});  // SPEC §10
  p.h_N = s.vector2("h_N", p.h_N);
  p.h = s.number("h", p.h, kSize);
  p.mesh = resolve_path(s.text("mesh", ""), case_path);
  p.geo = resolve_path(s.text("geo", ""), case_path);
  p.shape = s.choice("shape", !p.mesh.empty() ? "mesh" : !p.geo.empty() ? "geo" : "rectangle",
                     {"rectangle", "mesh", "geo", "none"});
  p.model = s.choice("model", p.model, {"linear", "saint-venant-kirchhoff", "neo-hookean"});
  p.element = s.choice("element", p.element, {"P1", "P2"});
  p.mesher = s.choice("mesher", p.mesher, {"lattice", "gmsh"});
  p.rho = s.number("rho", p.rho, {1e-30, 1e30, true, true});  // SPEC §12
  p.v0 = s.vector2("v0", p.v0);
  p.clamped = s.boolean("clamped", p.clamped);
  p.mass = s.choice("mass", p.mass, {"redistributed", "consistent"});
  check_shape_files(p, origin);
  s.reject_unknown();
}

void read_obstacle(const toml::table& root, const Origin& origin, Case& c, std::vector<std::string>* known) {
  Section s(section_table(root, "obstacle", origin), "obstacle", origin, known);
  auto& p = c.obstacle;
  p.x0 = s.number("x0", p.x0, kSigned);
  p.y0 = s.number("y0", p.y0, kSigned);
  p.r = s.number("r", p.r, kSize);
  p.gamma = s.number("gamma", p.gamma, open(0, 1));
  s.reject_unknown();
}

// SPEC §13's keys: the linear solver and an iterative one's controls.
void read_linear_solver(Section& s, const Origin& origin, FluidParams& p, bool schur_given) {
  p.linear_solver = s.choice("linear_solver", p.linear_solver, {"mumps", "petsc-mumps", "petsc-iterative"});
  p.linear_tol = s.number("linear_tol", p.linear_tol, {1e-15, 1e-2, true, true});
  p.linear_max_iterations = s.integer("linear_max_iterations", p.linear_max_iterations, 1, 100000);
  p.krylov = s.choice("krylov", p.krylov, {"gmres", "bicgstab"});
  if (p.linear_solver == "mumps") {
    // Each rank would factorise the whole system alone (SPEC §13).
    if (const int ranks = launched_ranks(); ranks > 1)
      fail(origin, "fluid.linear_solver", "= \"mumps\" runs on one rank; this run has " + std::to_string(ranks),
           "\"petsc-mumps\" or \"petsc-iterative\" under mpirun");
    return;
  }
  // The substructured solve condenses the far field with MUMPS's Schur complement,
  // which PETSc does not offer.
  if (schur_given)
    fail(origin, "fluid.factorization", "= \"schur\" needs fluid.linear_solver = \"mumps\"",
         "\"whole\" (the default with a PETSc solver)");
  // The split's Schur approximation (petsc_plugin.cpp) ignores the convection: GMRES
  // broke down or took 150–500 iterations on a Reynolds-25 cavity (measured); a
  // convection-aware one (PCD, LSC) is not built yet. Taylor–Hood's is not tested.
  if (p.linear_solver == "petsc-iterative" && (p.navier_stokes() || p.element == "taylor-hood"))
    fail(origin, "fluid.linear_solver", "= \"petsc-iterative\" is offered for the mini element's Stokes only",
         "\"mumps\" or \"petsc-mumps\" with fluid.model = \"navier-stokes\" or fluid.element = \"taylor-hood\"");
  if (p.method == "body-fitted")
    fail(origin, "fluid.linear_solver", "= \"" + p.linear_solver + "\" is not offered with fluid.method = \"body-fitted\"",
         "\"mumps\"");
  p.factorization = "whole";
}

// SPEC §10's keys: the model, its density and Newton's controls, the viscous form.
void read_fluid_model(Section& s, const Origin& origin, FluidParams& p) {
  const bool schur_given = s.has("factorization") && p.factorization == "schur";
  p.model = s.choice("model", p.model, {"stokes", "navier-stokes"});
  p.rho = s.number("rho", p.rho, {1e-30, 1e30, true, true});
  p.newton_tol = s.number("newton_tol", p.newton_tol, {1e-15, 1e-2, true, true});
  p.newton_max_steps = s.integer("newton_max_steps", p.newton_max_steps, 1, 1000);
  p.viscous_form = s.choice("viscous_form", p.viscous_form, {"symmetric", "gradient"});
  p.element = s.choice("element", p.element, {"mini", "taylor-hood"});
  if (!p.navier_stokes()) return;
  if (p.rho == 0)
    fail(origin, "fluid.rho", "is required with fluid.model = \"navier-stokes\"", "a density in [1e-30, 1e30] kg/m³");
  // Newton's Jacobian is unsymmetric and changes everywhere at every step: the far
  // field's Schur complement (symmetric, kept for the run) does not apply.
  if (schur_given)
    fail(origin, "fluid.factorization", "= \"schur\" factors symmetric systems only, and fluid.model = "
         "\"navier-stokes\" is not one", "\"whole\" (the default with navier-stokes)");
  p.factorization = "whole";
}

void read_fluid(const toml::table* fluid, const Origin& origin, const std::string& case_path, Case& c,
                std::vector<std::string>* known) {
  Section s(fluid, "fluid", origin, known);
  FluidParams p;
  p.L1 = s.number("L1", p.L1, kSize);
  p.H1 = s.number("H1", p.H1, kSize);
  p.H2 = s.number("H2", p.H2, {0, kMaxMagnitude, true, true});  // 0: the box starts at y = 0 (SPEC §10, DFG)
  p.mu = s.number("mu", p.mu, kSize);
  const std::array<double, 4> box = {0, -p.H2, p.L1, p.H1};  // where an expression's magnitude is sampled
  p.f = s.vector2_or_expressions("f", p.f, p.f_expression, box);  // SPEC §10: numbers or expressions in x, y, t
  p.Vmax = s.number_or_expression("Vmax", p.Vmax, kSigned, p.Vmax_expression, box);
  for (std::size_t k = 0; k < kBoxSideKeys.size(); ++k)
    p.sides[k] = s.choice(kBoxSideKeys[k], p.sides[k], {"wall", "inflow", "outflow"});
  p.h = s.number("h", p.h, kSize);
  p.mesh = resolve_path(s.text("mesh", ""), case_path);
  p.mesher = s.choice("mesher", p.mesher, {"lattice", "gmsh"});
  p.chi = s.choice("chi", p.chi, {"barycentre", "area-fraction"});
  p.factorization = s.choice("factorization", p.factorization, {"schur", "whole"});
  p.keep_far_factors_mb = s.number("keep_far_factors_mb", p.keep_far_factors_mb, kNonNegative);
  // A refinement's size: 0 (off) or at most the far size h.
  const auto refined_size = [&](const char* key, double value, const char* zero) {
    value = s.number(key, value, {0, kMaxMagnitude, true, true});
    if (value != 0 && !(value >= kMinMagnitude && value <= p.h))
      fail(origin, std::string("fluid.") + key, "= " + shortest(value) + " is out of range",
           std::string("0 (") + zero + ") or [1e-30, fluid.h = " + shortest(p.h) + "]");
    return value;
  };
  p.h_near = refined_size("h_near", p.h_near, "no band");
  s.band("band", p.band, p.band_box);
  p.h_obstacles = refined_size("h_obstacles", p.h_obstacles, "none");
  p.method = s.choice("method", p.method, {"penalised", "body-fitted"});
  const bool schur_given = s.has("factorization") && p.factorization == "schur";
  read_fluid_model(s, origin, p);
  read_linear_solver(s, origin, p, schur_given);
  s.reject_unknown();
  c.fluid = p;
}

// eps_rule = "layer": ε from the fluid's size at the structure; a stated ε must be
// that one (a resolved case written back, or a study's level, states it).
void apply_layer_rule(const Origin& origin, Case& c) {
  const double eps = layer_eps(c.fluid->mu, c.fluid->size_near());
  auto& k = c.coupling;
  if (k.eps_given && std::abs(k.eps - eps) > 1e-9 * eps)
    fail(origin, "coupling.eps", "= " + shortest(k.eps) + " contradicts coupling.eps_rule = \"layer\", which sets ε = " +
         shortest(eps) + " from fluid.mu and the fluid's size at the structure",
         "leave coupling.eps out, or coupling.eps_rule = \"fixed\"");
  if (!(eps >= 1e-12 && eps <= kMaxMagnitude))
    fail(origin, "coupling.eps_rule", "= \"layer\" gives ε = " + approx(eps, 3) + " for fluid.mu = " +
         shortest(c.fluid->mu) + " and a size of " + shortest(c.fluid->size_near()) + " at the structure",
         "ε in [1e-12, 1e30]: coupling.eps_rule = \"fixed\" with coupling.eps");
  k.eps = eps;
  // The force's integral resolves the layer it sets: eq. (33) sampled on sub-triangles
  // no wider than the layer (at the structure's vertices alone, a layer thinner than
  // the structure's triangles is overestimated by about their ratio: 21.1 against
  // 18.6 mm on the no-contact case, docs/validation.md "The penalty's error"). A
  // structure read from a file has no stated size: sampled at its vertices.
  if (!k.force_sampling_given && c.fluid->method == "penalised" && c.structure.element == "P1" &&
      c.structure.mesh.empty())
    k.force_sampling = layer_sampling(c.structure.h, CouplingParams::kLayerFraction * c.fluid->size_near());
}

void read_coupling(const toml::table& root, const Origin& origin, Case& c, std::vector<std::string>* known) {
  Section s(section_table(root, "coupling", origin), "coupling", origin, known);
  auto& p = c.coupling;
  // Below 1e-12 the penalty outweighs the viscous term by over 1e10 per element
  // (hF = 0.01, μ_F = 0.0035) and the fluid system loses its digits; ε = 1e-300
  // overflows outright.
  p.eps = s.number("eps", p.eps, {1e-12, kMaxMagnitude, true, true});
  p.eps_given = s.has("eps");
  p.eps_rule_given = s.has("eps_rule");
  p.omega = s.number("omega", p.omega, left_open(0, 1));
  p.tol = s.number("tol", p.tol, kSize);
  p.max_iterations = s.integer("max_iterations", p.max_iterations, 0, case_limits().max_iterations);
  p.scheme = s.choice("scheme", p.scheme, {"constant", "aitken", "iqn-ils"});
  p.reuse = s.integer("reuse", p.reuse, 0, 100);  // SPEC §12: IQN-ILS's pairs of past time steps
  p.eps_rule = s.text("eps_rule", p.eps_rule);
  if (!eps_rule_power(p.eps_rule))
    fail(origin, "coupling.eps_rule", "= \"" + p.eps_rule + "\" is not a known rule",
         "\"fixed\", \"layer\", or \"h^p\" with 0 < p <= 4 (for example \"h^2\")");
  p.force = s.choice("force", p.force, {"small", "large"});
  p.force_sampling = s.integer("force_sampling", p.force_sampling, 1, 8);
  p.force_sampling_given = s.has("force_sampling");
  if (p.eps_rule == "layer" && c.fluid) apply_layer_rule(origin, c);
  s.reject_unknown();
}

void read_output(const toml::table& root, const Origin& origin, Case& c, std::vector<std::string>* known) {
  Section s(section_table(root, "output", origin), "output", origin, known);
  c.output.dir = s.text("dir", "out/" + c.name);
  c.output.dir_origin = origin.of("output.dir");
  c.output.png = s.boolean("png", c.output.png);
  c.output.vtu = s.boolean("vtu", c.output.vtu);
  c.output.vtu_format = s.choice("vtu_format", c.output.vtu_format, {"binary", "zlib", "ascii"});
  c.output.probes = read_probes(s, origin);
  c.output.fluid_probes = read_probes(s, origin, "fluid_probes");
  const std::string problem = output_path_problem(c.output.dir);
  if (!problem.empty()) fail(origin, "output.dir", problem, "a directory path");
  s.reject_unknown();
}

// [time] (SPEC §12). `known` (the keys' enumeration): read with nothing required.
void read_time(const toml::table& root, const Origin& origin, Case& c, std::vector<std::string>* known) {
  const toml::table* table = section_table(root, "time", origin);
  if (!table && !known) return;
  Section s(table, "time", origin, known);
  TimeParams p;
  p.dt = s.number("dt", p.dt, kSize);
  p.t_end = s.number("t_end", p.t_end, kSize);
  p.scheme = s.choice("scheme", p.scheme, {"bdf1", "bdf2"});
  p.output_every = s.integer("output_every", p.output_every, 1, 1000000000);
  p.checkpoint_every = s.integer("checkpoint_every", p.checkpoint_every, 0, 1000000000);
  p.start_from = s.choice("start_from", p.start_from, {"rest", "steady"});
  p.convection = s.choice("convection", p.convection, {"implicit", "semi-implicit"});
  s.reject_unknown();
  if (known) return;
  for (const char* key : {"dt", "t_end"})
    if (!s.has(key)) fail(origin, std::string("time.") + key, "is required in [time]", "a time in seconds, > 0");
  if (!(p.dt <= p.t_end))
    fail(origin, "time.dt", "= " + shortest(p.dt) + " exceeds time.t_end = " + shortest(p.t_end),
         "(0, time.t_end]");
  const double max_steps = case_limits().time_steps;
  if (p.t_end / p.dt > max_steps)
    fail(origin, "time.t_end", "/ time.dt = " + shortest(p.t_end / p.dt) + " steps is over the limit",
         "at most " + shortest(max_steps) + " steps");
  const double frames = std::floor(p.t_end / p.dt / p.output_every) + 1, max_frames = case_limits().time_frames;
  if (frames > max_frames)
    fail(origin, "time.output_every", "= " + std::to_string(p.output_every) + " writes " + shortest(frames) +
         " frames, over the limit", "at least " + shortest(std::ceil(p.t_end / p.dt / (max_frames - 1))) +
         " (at most " + shortest(max_frames) + " frames)");
  c.time = p;
}

// `known`, if given, collects every key read (case_keys()).
Case read_case(const toml::table& root, const Origin& origin, const std::string& case_path, bool has_fluid_default,
               std::vector<std::string>* known = nullptr) {
  Case c;
  c.source = origin.file;
  {
    Section top(&root, "", origin, known);
    c.name = top.text("name", case_path.empty() ? c.name : std::filesystem::path(case_path).stem().string());
    for (auto&& [k, v] : root)
      if (!kSections.count(std::string(k.str())))
        fail(origin, std::string(k.str()), "is not a known key or section",
             "name, [structure], [obstacle], [[obstacles]], [fluid], [coupling], [contact], [output], [time]");
    check_name(c.name, origin);
  }
  read_structure(root, origin, case_path, c, known);
  c.obstacle_given = root.contains("obstacle");
  read_obstacle(root, origin, c, known);
  read_obstacles(root, origin, c);
  const toml::table* fluid = section_table(root, "fluid", origin);
  if (fluid || has_fluid_default || known)
    read_fluid(fluid, origin, case_path, c, known);
  else
    c.fluid.reset();
  read_coupling(root, origin, c, known);
  {
    Section s(section_table(root, "contact", origin), "contact", origin, known);
    c.contact.solver = s.choice("solver", c.contact.solver, {"active-set", "ipopt"});
    c.contact.gap = s.choice("gap", c.contact.gap, {"paper", "normal"});
    c.contact.boundary = s.choice("boundary", c.contact.boundary, {"Gamma_C", "all"});
    s.reject_unknown();
  }
  // obstacles = []: no contact can happen, so neither contact.gap nor contact.boundary
  // matters; they resolve to what needs no obstacle (eq. 15's gap is one disk's, and a
  // generated rectangle's Gamma_C that disk's span).
  if (c.obstacles_given && c.obstacles.empty()) c.contact.gap = "normal", c.contact.boundary = "all";
  read_output(root, origin, c, known);
  read_time(root, origin, c, known);
  check_case(c, origin);
  return c;
}

// Applies the overrides, then the output directory given on the command line: taken
// as it is, never parsed (a path is data: "C:\temp" stays seven characters).
Case read_with_overrides(toml::table& root, Origin& origin, const std::string& case_path, bool has_fluid_default,
                         const std::vector<std::string>& overrides, const std::string& out_dir) {
  for (const auto& o : overrides) apply_override(root, o, origin);
  if (!out_dir.empty()) {
    if (!root.contains("output")) root.insert("output", toml::table{});
    toml::table* output = root["output"].as_table();
    if (!output) fail(origin, "output", "must be a table ([output])", "");
    output->insert_or_assign("dir", out_dir);
    origin.overridden.insert("output.dir");
  }
  Case c = read_case(root, origin, case_path, has_fluid_default);
  if (!out_dir.empty()) c.output.dir_origin = "--out";
  return c;
}

// [[x, y], ...] (a polygon's corners, output.probes), each number as it was read.
toml::array points_toml(const std::vector<Point>& points) {
  toml::array a;
  for (const Point& p : points) a.push_back(toml::array{p.x(), p.y()});
  return a;
}

// A load of SPEC §10 as it was given: a number as a number, an expression as its text.
void insert_load(toml::table& t, const char* key, double value, const std::string& expression) {
  if (expression.empty()) t.insert_or_assign(key, value);
  else t.insert_or_assign(key, expression);
}
toml::array load_toml(const Point& p, const std::array<std::string, 2>& expressions) {
  toml::array a;
  for (int c = 0; c < 2; ++c)
    if (expressions[c].empty()) a.push_back(p[c]);
    else a.push_back(expressions[c]);
  return a;
}

InputError parse_error(const std::string& where, const toml::parse_error& e) {
  return InputError(where + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
}

}  // namespace

Case load_case(const std::string& path, const std::vector<std::string>& overrides, const std::string& out_dir) {
  Origin origin{path.empty() ? "(built-in paper-7.2 case)" : path, {}};
  toml::table root;
  if (!path.empty()) {
    if (const std::string problem = input_file_problem(path, "case", "a regular TOML file (e.g. cases/paper-7.2.toml)");
        !problem.empty())
      throw InputError(path + ": " + problem);
    try {
      root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
      throw parse_error(path, e);
    }
  }
  return read_with_overrides(root, origin, path, /*has_fluid_default=*/path.empty(), overrides, out_dir);
}

Case load_case_text(const std::string& text, const std::string& origin_name, const std::vector<std::string>& overrides,
                    const std::string& out_dir) {
  Origin origin{origin_name, {}};
  toml::table root;
  try {
    root = toml::parse(text, origin_name);
  } catch (const toml::parse_error& e) {
    throw parse_error(origin_name, e);
  }
  return read_with_overrides(root, origin, "", /*has_fluid_default=*/false, overrides, out_dir);
}

CaseSource CaseSource::text_named(std::string toml_text, std::string origin) {
  CaseSource s(std::move(origin));
  s.text = std::move(toml_text);
  return s;
}

Case CaseSource::load(const std::vector<std::string>& overrides, const std::string& out_dir) const {
  return text ? load_case_text(*text, path, overrides, out_dir) : load_case(path, overrides, out_dir);
}

int layer_sampling(double h_S, double layer) {
  const double m = std::ceil(h_S / layer * (1 - 1e-12));  // h_S = 3 layers exactly: 3, not 4
  return static_cast<int>(std::clamp(m, 1.0, 8.0));
}

double layer_eps(double mu, double h) {
  const double layer = CouplingParams::kLayerFraction * h;
  return layer * layer / mu;
}

double CouplingParams::eps_power() const { return eps_rule_power(eps_rule).value_or(0.0); }

CaseLimits& case_limits() {
  static CaseLimits limits;
  return limits;
}

double fluid_triangle_limit(const FluidParams& f) {
  return f.linear_solver == "petsc-iterative" ? case_limits().fluid_triangles_iterative
                                              : case_limits().fluid_triangles;
}

std::vector<std::string> case_keys() {
  std::vector<std::string> keys;
  read_case(toml::table{}, Origin{"(keys)", {}}, "", /*has_fluid_default=*/true, &keys);
  return keys;
}

namespace {

// [fluid] of the resolved case.
toml::table fluid_toml(const FluidParams& f) {
  toml::table ft{{"L1", f.L1}, {"H1", f.H1}, {"H2", f.H2}, {"mu", f.mu},   {"f", load_toml(f.f, f.f_expression)},
                 {"h", f.h}, {"chi", f.chi}, {"factorization", f.factorization},
                 {"keep_far_factors_mb", f.keep_far_factors_mb}, {"h_near", f.h_near},
                 {"h_obstacles", f.h_obstacles}, {"method", f.method},
                 {"model", f.model}, {"viscous_form", f.viscous_form}, {"element", f.element}, {"newton_tol", f.newton_tol},
                 {"newton_max_steps", f.newton_max_steps}, {"linear_solver", f.linear_solver},
                 {"linear_tol", f.linear_tol}, {"linear_max_iterations", f.linear_max_iterations},
                 {"krylov", f.krylov}};
  insert_load(ft, "Vmax", f.Vmax, f.Vmax_expression);
  if (f.rho > 0) ft.insert("rho", f.rho);  // 0: not given
  if (f.band_box) ft.insert("band", toml::array{(*f.band_box)[0], (*f.band_box)[1], (*f.band_box)[2], (*f.band_box)[3]});
  else ft.insert("band", f.band);
  if (!f.mesh.empty()) ft.insert("mesh", f.mesh);
  if (f.mesher != "lattice") ft.insert("mesher", f.mesher);
  for (std::size_t k = 0; k < kBoxSideKeys.size(); ++k) ft.insert(kBoxSideKeys[k], f.sides[k]);
  return ft;
}

}  // namespace

std::string to_toml(const Case& c) {
  auto vec = [](const Point& p) { return toml::array{p.x(), p.y()}; };
  toml::table t;
  t.insert("name", c.name);
  const auto& s = c.structure;
  toml::table st{{"shape", s.shape}, {"E", s.E}, {"nu", s.nu}, {"f", load_toml(s.f, s.f_expression)}, {"h_N", vec(s.h_N)}, {"h", s.h}};
  if (s.rectangle() || s.extent_given) st.insert("L", s.L), st.insert("H", s.H);  // a file's own extent otherwise
  if (!s.mesh.empty()) st.insert("mesh", s.mesh);
  if (!s.geo.empty()) st.insert("geo", s.geo);
  if (s.model != "linear") st.insert("model", s.model);  // the default stays unwritten (Table 1's case.toml)
  if (s.element != "P1") st.insert("element", s.element);
  if (s.mesher != "lattice") st.insert("mesher", s.mesher);
  if (s.rho > 0) st.insert("rho", s.rho), st.insert("v0", vec(s.v0)), st.insert("mass", s.mass);
  if (!s.clamped) st.insert("clamped", false);
  t.insert("structure", st);
  const auto& o = c.obstacle;
  if (!c.obstacles_given) {
    t.insert("obstacle", toml::table{{"x0", o.x0}, {"y0", o.y0}, {"r", o.r}, {"gamma", o.gamma}});
  } else {
    toml::array list;
    for (const ObstacleSpec& b : c.obstacles) {
      toml::table e{{"shape", b.shape}};
      if (b.shape == "disk") e.insert("x0", b.x0), e.insert("y0", b.y0), e.insert("r", b.r);
      if (b.shape == "half-plane")
        e.insert("point", toml::array{b.point.x(), b.point.y()}), e.insert("normal", toml::array{b.normal.x(), b.normal.y()});
      if (b.shape == "polygon") {
        e.insert("points", points_toml(b.points));
      }
      list.push_back(e);
    }
    t.insert("obstacles", list);
  }
  if (c.fluid) t.insert("fluid", fluid_toml(*c.fluid));
  const auto& k = c.coupling;
  toml::table coupling{{"eps", k.eps}, {"omega", k.omega}, {"tol", k.tol}, {"max_iterations", k.max_iterations},
                      {"scheme", k.scheme}, {"eps_rule", k.eps_rule}};
  if (k.force != "small") coupling.insert("force", k.force);  // the default stays unwritten
  if (k.force_sampling != 1) coupling.insert("force_sampling", k.force_sampling);
  if (k.reuse != CouplingParams{}.reuse) coupling.insert("reuse", k.reuse);
  t.insert("coupling", coupling);
  t.insert("contact", toml::table{{"solver", c.contact.solver}, {"gap", c.contact.gap}, {"boundary", c.contact.boundary}});
  toml::table output{{"dir", c.output.dir}, {"png", c.output.png}, {"vtu", c.output.vtu}};
  if (c.output.vtu_format != "binary") output.insert("vtu_format", c.output.vtu_format);
  if (!c.output.probes.empty()) output.insert("probes", points_toml(c.output.probes));
  if (!c.output.fluid_probes.empty()) output.insert("fluid_probes", points_toml(c.output.fluid_probes));
  t.insert("output", output);
  if (c.time)
    t.insert("time", toml::table{{"dt", c.time->dt}, {"t_end", c.time->t_end}, {"scheme", c.time->scheme},
                                 {"output_every", c.time->output_every},
                                 {"checkpoint_every", c.time->checkpoint_every},
                                 {"start_from", c.time->start_from},
                                 {"convection", c.time->convection}});
  std::ostringstream out;
  out << t << "\n";
  return out.str();
}

}  // namespace fsi
