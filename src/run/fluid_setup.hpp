// Everything about the fluid that a run builds once: the fixed mesh of D, its point
// locator, the χ rule, and the penalised Stokes system with the box's boundary
// conditions (SPEC §3, §10).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "fluid/chi.hpp"
#include "fluid/fluid_field.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fluid/stokes_residual.hpp"
#include "fluid/time_derivative.hpp"
#include "io/case.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/case_fields.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

struct FluidSetup {
  std::unique_ptr<Mesh> mesh;  // owned here: the solver and locator refer to it
  std::unique_ptr<PointLocator> locator;
  std::unique_ptr<ChiComputer> chi;
  std::unique_ptr<PenalisedStokes> stokes;
};

// D's holes for the generated box (FluidGeometry::holes, mesh/gmsh_io.hpp): every
// obstacle of [[obstacles]] in case order (SPEC §9; disks and polygons:
// check_fluid_obstacles), or nullopt for [obstacle]'s one disk.
std::optional<std::vector<FluidHole>> case_holes(const Case& c);

// Generates or reads the mesh of D: a bad user file is an InputError, a failure to
// mesh validated geometry a SolverFailure. Depends on fluid.* and obstacle.*, and on
// `band` (fluid_band_box, run/fluid_band.hpp: h_near's box, nullopt without h_near).
Mesh build_fluid_mesh(const Case& c, const std::optional<std::array<double, 4>>& band);
// build_fluid_mesh (the band from a structure setup made here if it needs one), then
// (a mesh file) check_fluid_mesh against the case's keys.
Mesh make_fluid_mesh(const Case& c);

// The conditions of fluid.left, bottom, right, top on the labels Σ1 … Σ4 (SPEC §10
// "Box sides": v = 0 on a wall, the parabolic inflow into the box, an outflow
// traction-free) and v = 0 on Σ5 (every hole: hole_labels). The defaults are the
// paper's §3: v = g on Σ4 with g = (0, Vmax·4x(x − L1)/L1²), v = 0 on Σ1, Σ3, Σ5, Σ2
// traction-free.
// `t`: the time fluid.Vmax is evaluated at (an expression in t, SPEC §12).
FluidBoundaryConditions box_boundary_conditions(const Mesh& mesh, const FluidParams& f, double t = kSteadyTime);

FluidSetup make_fluid(const Case& c, Mesh mesh, double eps);

// fluid.viscous_form and fluid.model (SPEC §10) on a solver made with the whole
// factorisation and kNavierStokesSolver for Navier–Stokes; and the same operator for
// the residual forces.
// `semi_implicit`: time.convection = "semi-implicit" (a time run's).
void set_fluid_model(PenalisedStokes& stokes, const FluidParams& f, bool semi_implicit = false);
MomentumModel momentum_model(const FluidParams& f);
// time.scheme (SPEC §12) as the fluid's BDF.
inline TimeScheme time_scheme(const TimeParams& p) { return p.scheme == "bdf2" ? TimeScheme::bdf2 : TimeScheme::bdf1; }

// One solve for `chi` (the fluid alone: around the structure at rest, or with no
// structure), exact everywhere; SolverFailure "the fluid solve failed: ..." or on a
// non-finite field.
const FluidSolution& solve_fluid_once(PenalisedStokes& stokes, const Eigen::VectorXd& chi);

// summary.json's "fluid" of the penalised method: sizes, solver, factorisations and
// their timings, the substructured solve's region.
Json fluid_json(const PenalisedStokes& stokes);
// fluid_json's linear_solver (SPEC §13: "mumps" for every direct solver called directly)
// and, for "petsc-iterative", linear_iterations per solve and their total.
void add_linear_solver_json(Json& j, const std::string& solver, const std::vector<int>& iterations,
                            const std::string& krylov);

// The Reynolds number ρ Ū L / μ of a Navier–Stokes case (SPEC §10): Ū = 2 Vmax / 3,
// the parabolic inflow's mean, and L the first obstacle's width across the inflow
// (a disk's diameter: the DFG benchmarks' Re = 20) or, without one, the inflow side's
// length. NaN for Stokes or without an inflow.
struct Reynolds {
  double value = NAN, U = NAN, L = NAN;
  std::string length;  // what L is, in words
};
Reynolds reynolds_number(const Case& c);
// summary.json's fluid.model and fluid.reynolds (value, mean_inflow_velocity, length).
Json flow_json(const Case& c);
Json newton_json(const FluidNewtonReport& n);

}  // namespace fsi
