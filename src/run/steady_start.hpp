// time.start_from = "steady" (SPEC §12): a time run that starts from the steady
// solution of its own case, with the data at t = 0, instead of from rest. The
// structure's steady problem is solved on a setup of its own, without inertia (the time
// run's operator holds A_S + (4/Δt²) M); the coupled one by the fixed point of §5 with
// the steady fluid (no time derivative yet) and eq. (33)'s force, as a steady run
// solves it. Its acceleration is zero: it is in equilibrium.
#pragma once

#include "coupling/force_transfer.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// The contact problem for the applied load at t = 0. SolverFailure names the start.
ContactSolution steady_structure(const Case& c);

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
