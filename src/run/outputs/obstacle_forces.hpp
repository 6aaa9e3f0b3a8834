// summary.json's obstacles[i].force (SPEC §10 "Forces"): the force of the fluid on
// each obstacle of [[obstacles]] in a coupled run, N per metre of depth, by the
// residual (volume) method: the weak residual of the penalised momentum equation
// (25) tested with φ_j e_c summed over the obstacle's hole Σ5_i (a function equal to
// e_c on that hole's vertices, zero on every other Dirichlet side), with its sign
// turned (fluid/stokes_residual.hpp: R is what the fluid receives). The penalty
// (1/ε)∫χ v·w is part of the residual: R is then exactly the reaction of the
// discrete system's removed rows, also where the structure covers part of a hole's
// boundary (there it counts the fictitious fluid inside the structure, v ≈ 0).
#pragma once

#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

// The obstacles' holes in the case's order, by their labels' names: Sigma_5_i of
// [[obstacles]], or Sigma_5 for [obstacle]'s one disk.
std::vector<std::string> obstacle_hole_names(const Case& c);

// [{"force": [Fx, Fy]}, ...] in the case's order ([obstacle]'s disk: one), from the last fluid solution (made
// exact everywhere first); a force that cannot be computed (no solution, or its
// completion failed) is null.
Json obstacle_forces_json(const Case& c, FluidSetup& f);

// The same list from a solution `s` on `mesh` (null: forces null, mesh unused) computed with the
// penalty `kappa` = χ/ε per triangle (empty for the body-fitted fluid, which has no
// penalty); the holes labelled Sigma_5_i, or Sigma_5 for [obstacle].
Json hole_forces_json(const Case& c, const Mesh& mesh, const FluidSolution* s, const Eigen::VectorXd& kappa);

// The same list from forces already computed, one per hole (null: each force null).
Json hole_forces_json(const Case& c, const std::vector<Point>* forces);

// summary.json's fluid_at (output.fluid_probes, SPEC §10): [{"point", "v", "p"}, ...],
// the flow at each probe (bubble included; a probe just off the meshed boundary read at
// its nearest boundary point); v and p null without a solution.
Json fluid_probes_json(const Case& c, const Mesh& mesh, const FluidSolution* s);
Json fluid_probes_json(const Case& c, FluidSetup& f);

}  // namespace fsi
