#include "run/steady_start.hpp"

#include "common/errors.hpp"
#include "coupling/penalised_step.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {
namespace {

constexpr const char* kWhat = "the steady state at t = 0 (time.start_from = \"steady\"): ";

// The case's structure without its inertia, meshed again (a P2 setup's mesh is its
// nodal one: the time run's cannot be handed over).
StructureSetup steady_setup(const Case& c) {
  Case steady = c;
  steady.time.reset();
  return make_structure(steady, make_structure_mesh(steady), nullptr);
}

}  // namespace

ContactSolution steady_structure(const Case& c) {
  StructureSetup s = steady_setup(c);
  try {
    return s.gap->solve(*s.solver, s.b_applied, {}, nullptr);
  } catch (const QpError& e) {
    throw SolverFailure(std::string(kWhat) + "the contact QP failed: " + e.what());
  } catch (const SolverFailure& e) {
    throw SolverFailure(std::string(kWhat) + e.what());
  }
}

CouplingResult couple_steady(const Case& c, const Mesh& structure_mesh, FluidSetup& f, const FluidForce& force,
                             StructureStep& structure, const Eigen::VectorXd& b,
                             const std::function<void(FixedPointCoupling&)>& configure) {
  const SparseMatrix M = assemble_vector_mass(structure_mesh);  // L²(Ω_S0): the stop's and the relaxation's
  auto relaxation = make_relaxation(c.coupling.scheme, {.omega0 = c.coupling.omega}, M);
  PenalisedStep fluid({structure_mesh, *f.stokes, *f.locator, *f.chi, force});
  FixedPointCoupling loop(fluid, structure, b, *relaxation, M, c.coupling.tol, c.coupling.max_iterations);
  if (configure) configure(loop);
  return loop.run();
}

SteadyCoupledStart steady_coupled(const Case& c, const StructureSetup& s, FluidSetup& f, const FluidForce& force) {
  StructureSetup steady = steady_setup(c);
  StructureStep structure(*steady.solver, steady.gap.get());
  CouplingResult r = couple_steady(c, s.mesh(), f, force, structure, steady.b_applied);
  if (!r.failure.empty()) throw SolverFailure(kWhat + r.failure);
  if (!r.converged)
    throw SolverFailure(std::string(kWhat) + "the coupling did not converge in coupling.max_iterations = " +
                        std::to_string(c.coupling.max_iterations) + " passes");
  SteadyCoupledStart start{r.structure, f.stokes->solution(), r.fluid_load, r.iterations};
  start.fluid.exact_on = nullptr;
  return start;
}

}  // namespace fsi
