#include "run/fluid_setup.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_band.hpp"
#include "run/hole_checks.hpp"
#include "run/mesh_checks.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

std::optional<std::vector<FluidHole>> case_holes(const Case& c) {
  if (!c.obstacles_given) return std::nullopt;
  std::vector<FluidHole> holes;
  for (const ObstacleSpec& b : c.obstacles) holes.push_back({b.x0, b.y0, b.r, b.points});
  return holes;
}

Mesh build_fluid_mesh(const Case& c, const std::optional<std::array<double, 4>>& band) {
  const FluidParams& f = *c.fluid;
  const ObstacleParams& o = c.obstacle;
  if (f.mesh.empty()) {
    try {
      FluidGeometry g{f.L1, f.H1, f.H2, o.x0, o.y0, o.r, f.h};
      if (band) g.h_near = f.h_near, g.band = *band;
      g.h_holes = f.h_obstacles;
      g.holes = case_holes(c);
      return generate_fluid_mesh(g, mesh_generator(f.mesher));
    } catch (const MeshError& e) {  // the geometry was validated: the generator's failure
      throw SolverFailure(std::string("meshing the fluid box failed: ") + e.what());
    }
  }
  if (!c.obstacles_given)
    return read_case_mesh(c, "fluid.mesh", f.mesh, {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4", "Sigma_5"}, "D",
                          fluid_triangle_limit(f));
  // [[obstacles]]: a hole per obstacle (SPEC §9), checked by check_fluid_mesh.
  Mesh mesh = read_case_mesh(c, "fluid.mesh", f.mesh, {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4"}, "D",
                             fluid_triangle_limit(f), mesh_hole_groups(c));
  name_mesh_holes(c, mesh);
  return mesh;
}

Mesh make_fluid_mesh(const Case& c) {
  std::optional<std::array<double, 4>> band;
  if (band_needs_structure(c)) {
    StructureSetup s = make_structure(c, make_structure_mesh(c), nullptr);
    band = fluid_band_box(c, &s);
  } else {
    band = fluid_band_box(c, nullptr);
  }
  Mesh mesh = build_fluid_mesh(c, band);
  if (!c.fluid->mesh.empty()) check_fluid_mesh(c, mesh);
  check_fluid_probes_inside(c, mesh);
  return mesh;
}

namespace {

// The inflow on side k (SPEC §10 "Box sides"): normal to the side, into the box, of
// magnitude Vmax·4s(ℓ − s)/ℓ², s the coordinate along the side from its lower or left
// end. It is written as Vmax·4s(s − ℓ)/ℓ² (≤ 0) times the outward normal's component,
// so that Σ4's is, bit for bit, the paper's g = (0, Vmax·4x(x − L1)/L1²) of §3. It
// vanishes at both ends: the corners shared with walls or other inflows agree. Vmax is
// fluid.Vmax at the point (SPEC §10: a number, or an expression in x, y, t at time t).
VectorField inflow(int k, const FluidParams& f, double t) {
  const ScalarField Vmax = inflow_peak(f, t);
  const double H2 = f.H2;
  const bool vertical = k == 0 || k == 2;           // Σ1, Σ3: along y
  const double l = vertical ? f.H1 + f.H2 : f.L1;   // ℓ
  const double outward = k == 0 || k == 1 ? -1 : 1;  // Σ1: −x, Σ2: −y, Σ3: +x, Σ4: +y
  if (vertical)
    return [=](const Point& x) {
      const double s = x.y() + H2;
      return Point(outward * (Vmax(x) * 4 * s * (s - l) / (l * l)), 0);
    };
  return [=](const Point& x) {
    const double s = x.x();
    return Point(0, outward * (Vmax(x) * 4 * s * (s - l) / (l * l)));
  };
}

}  // namespace

FluidBoundaryConditions box_boundary_conditions(const Mesh& mesh, const FluidParams& f, double t) {
  FluidBoundaryConditions bc;
  // On the labels, whatever their coordinates (a mesh whose Σk is not on side k is
  // refused by check_fluid_mesh). An outflow side is natural (traction-free), so it
  // is simply not Dirichlet. The defaults give the labels Σ1, Σ3, Σ4, Σ5 in this order.
  for (int k = 0; k < 4; ++k) {
    if (f.sides[k] == "outflow") continue;
    const int label = mesh.label("Sigma_" + std::to_string(k + 1));
    bc.dirichlet_labels.push_back(label);
    if (f.sides[k] == "inflow") bc.dirichlet_values.emplace_back(label, inflow(k, f, t));
  }
  for (int label : hole_labels(mesh)) bc.dirichlet_labels.push_back(label);  // Σ5: no-slip on every hole
  return bc;
}

FluidSetup make_fluid(const Case& c, Mesh mesh, double eps) {
  const FluidParams& f = *c.fluid;
  FluidSetup s;
  s.mesh = std::make_unique<Mesh>(std::move(mesh));
  // The substructured solve orders the unknowns on a second thread meanwhile, from
  // the start of the solver's set-up.
  const FluidFactorization factorization =
      f.factorization == "whole" ? FluidFactorization::whole : FluidFactorization::schur;
  s.stokes = std::make_unique<PenalisedStokes>(
      *s.mesh, f.mu, eps, fluid_body_force(f), box_boundary_conditions(*s.mesh, f),
      f.navier_stokes() ? kNavierStokesSolver : kDefaultSparseSolver, factorization, f.keep_far_factors_mb);
  if (f.linear_solver != "mumps")
    s.stokes->set_linear_solver(f.linear_solver, LinearSolverOptions(f.linear_tol, f.linear_max_iterations, f.krylov));
  set_fluid_model(*s.stokes, f, c.time && c.time->convection == "semi-implicit");
  s.locator = std::make_unique<PointLocator>(*s.mesh);
  s.chi = std::make_unique<ChiComputer>(*s.mesh, *s.locator, f.chi);
  return s;
}

void set_fluid_model(PenalisedStokes& stokes, const FluidParams& f, bool semi_implicit) {
  if (f.viscous_form == "gradient") stokes.set_viscous_form(ViscousForm::gradient);
  if (f.navier_stokes()) stokes.set_navier_stokes({f.rho, f.newton_tol, f.newton_max_steps, semi_implicit});
}

MomentumModel momentum_model(const FluidParams& f) {
  return {f.mu, f.viscous_form == "gradient" ? ViscousForm::gradient : ViscousForm::symmetric,
          f.navier_stokes() ? f.rho : 0.0};
}

const FluidSolution& solve_fluid_once(PenalisedStokes& stokes, const Eigen::VectorXd& chi) {
  stokes.set_chi(chi);
  const FluidSolution* solved = nullptr;
  try {
    solved = &stokes.solve();
  } catch (const SolverFailure& e) {  // named by its phase, as the coupling names its own
    throw SolverFailure(std::string("the fluid solve failed: ") + e.what());
  }
  const FluidSolution& v = *solved;
  if (!v.v1.allFinite() || !v.v2.allFinite() || !v.p.allFinite() || !v.bubble.allFinite())
    throw SolverFailure("the fluid solve gave a non-finite velocity or pressure");
  return v;
}

// Newton's iterations (SPEC §10): the run's totals, the last solve's residual history.
Json newton_json(const FluidNewtonReport& n) {
  return {{"solves", n.solves},
          {"steps", n.total_steps},
          {"picard_steps", n.total_picard_steps},
          {"last_steps", n.steps},
          {"last_damped_steps", n.damped},
          {"last_picard_steps", n.picard_steps},
          {"last_rejected_steps", n.rejected},
          {"last_residuals", n.residuals},
          {"max_final_residual", n.max_final_residual}};
}

namespace {

// The first obstacle's extent across a flow along `along` (0: x, 1: y), or NaN.
double obstacle_width(const Case& c, int along) {
  const int across = 1 - along;
  if (!c.obstacles_given) return 2 * c.obstacle.r;
  if (c.obstacles.empty()) return NAN;
  const ObstacleSpec& o = c.obstacles.front();
  if (o.shape == "disk") return 2 * o.r;
  if (o.shape != "polygon") return NAN;
  double lo = INFINITY, hi = -INFINITY;
  for (const Point& p : o.points) lo = std::min(lo, p[across]), hi = std::max(hi, p[across]);
  return hi - lo;
}

}  // namespace

Reynolds reynolds_number(const Case& c) {
  Reynolds re;
  const FluidParams& f = *c.fluid;
  int inflow = -1;
  for (int k = 0; k < 4; ++k)
    if (f.sides[k] == "inflow" && inflow < 0) inflow = k;
  if (!f.navier_stokes() || inflow < 0) return re;
  const int along = inflow == 0 || inflow == 2 ? 0 : 1;  // the flow's direction: x from Σ1, Σ3
  re.U = 2 * std::abs(f.Vmax) / 3;
  re.L = obstacle_width(c, along);
  re.length = "the first obstacle's width across the inflow";
  if (!std::isfinite(re.L)) {
    re.L = along == 0 ? f.H1 + f.H2 : f.L1;
    re.length = "the inflow side's length";
  }
  re.value = f.rho * re.U * re.L / f.mu;
  return re;
}

Json flow_json(const Case& c) {
  Json j = {{"model", c.fluid->model}, {"viscous_form", c.fluid->viscous_form}};
  const Reynolds re = reynolds_number(c);
  if (std::isfinite(re.value))
    j["reynolds"] = {{"value", re.value}, {"mean_inflow_velocity", re.U}, {"length", re.L}, {"length_is", re.length}};
  return j;
}

// SPEC §13: fluid.linear_solver as given, and an iterative solver's Krylov method and
// iterations per solve.
void add_linear_solver_json(Json& j, const std::string& solver, const std::vector<int>& iterations,
                            const std::string& krylov) {
  j["linear_solver"] = solver.rfind("petsc-", 0) == 0 ? solver : "mumps";
  if (solver != "petsc-iterative") return;
  j["krylov"] = krylov;
  j["linear_iterations"] = iterations;
  long total = 0;
  for (int n : iterations) total += n;
  j["linear_iterations_total"] = total;
}

Json fluid_json(const PenalisedStokes& stokes) {
  const FluidTiming& t = stokes.timing();
  Json j = {{"method", "penalised"},  // fluid.method (run/body_fitted_problem.cpp writes the other)
            {"element", "mini"},      // fluid.element (run/taylor_hood_setup.cpp writes the other)
            {"unknowns", stokes.unknowns()},
            {"nonzeros", stokes.nonzeros()},
            {"solver", stokes.solver_name()},
            {"analyses", t.analyses},  // symbolic analyses: 1 per run, 0 for a sweep row reusing it
            {"factorizations", t.factorizations},
            {"reused_solutions", t.reused},
            {"assembly_s", t.assembly},
            {"analysis_s", t.analysis},  // included in factorization_s
            {"factorization_s", t.factorization},
            {"solve_s", t.solve}};
  j["factorization"] = stokes.factorization() == FluidFactorization::schur ? "schur" : "whole";
  add_linear_solver_json(j, stokes.solver_name(), t.linear_iterations, stokes.linear_options().krylov);
  if (const FluidNewtonReport* n = stokes.newton()) j["newton"] = newton_json(*n);
  // The substructured solve: far-field factorisations (one per near region; their
  // time is part of factorization_s), the expansions (part of solve_s), the last
  // region's size.
  j["far_field_factorizations"] = t.regions;
  j["far_factorization_s"] = t.far_factorization;
  j["expansion_s"] = t.expansion;
  // Far fields over fluid.keep_far_factors_mb are refactorised for each expansion.
  j["far_factor_mb"] = stokes.region() ? stokes.region()->far_factor_mb() : 0.0;  // the region in use
  j["far_field_refactorizations"] = t.far_refactorizations;
  if (const RegionSchurSolver* r = stokes.region()) {
    j["near_unknowns"] = r->near_unknowns();
    j["interface_unknowns"] = r->interface_unknowns();
  }
  return j;
}

}  // namespace fsi
