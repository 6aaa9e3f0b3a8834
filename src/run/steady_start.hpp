// time.start_from = "steady" (SPEC §12): a time run that starts from the steady
// solution of its own case, with the data at t = 0, instead of from rest. The
// structure's steady problem is solved on a setup of its own, without inertia (the time
// run's operator holds A_S + (4/Δt²) M); the coupled one by the fixed point of §5 with
// the steady fluid (no time derivative yet) and eq. (33)'s force, as a steady run
// solves it. Its acceleration is zero: it is in equilibrium.
#pragma once

#include <functional>

#include "coupling/fixed_point.hpp"
#include "coupling/force_transfer.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// The contact problem for the applied load at t = 0. SolverFailure names the start.
ContactSolution steady_structure(const Case& c);

// The steady coupled problem of §5 on the structure's reference mesh `structure_mesh`:
// the fixed point of `c`'s relaxation over the penalised fluid step (eq. 33's `force`)
// and `structure`, for the applied load `b`. `configure` sets the loop's progress,
// observer or start before it runs. What the steady kind solves, and a steady start.
CouplingResult couple_steady(const Case& c, const Mesh& structure_mesh, FluidSetup& f, const FluidForce& force,
                             StructureStep& structure, const Eigen::VectorXd& b,
                             const std::function<void(FixedPointCoupling&)>& configure = {});

struct SteadyCoupledStart {
  ContactSolution structure;
  FluidSolution fluid;          // everywhere
  Eigen::VectorXd fluid_load;   // eq. (33)'s, on the structure's dofs
  int passes = 0;
};
// The steady coupled problem of `c` at t = 0 on the time run's meshes (`s`'s reference
// mesh, `f`'s fluid, before its time derivative is added). SolverFailure if it fails
// or does not converge in coupling.max_iterations passes.
SteadyCoupledStart steady_coupled(const Case& c, const StructureSetup& s, FluidSetup& f, const FluidForce& force);

}  // namespace fsi
