#include "run/steady_start.hpp"

#include "common/errors.hpp"
#include "coupling/fixed_point.hpp"
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

SteadyCoupledStart steady_coupled(const Case& c, const StructureSetup& s, FluidSetup& f, const FluidForce& force) {
  StructureSetup steady = steady_setup(c);
  const SparseMatrix M = assemble_vector_mass(s.mesh());
  auto relaxation = make_relaxation(c.coupling.scheme, {.omega0 = c.coupling.omega}, M);
  PenalisedStep fluid({s.mesh(), *f.stokes, *f.locator, *f.chi, force});
  StructureStep structure(*steady.solver, steady.gap.get());
  FixedPointCoupling loop(fluid, structure, steady.b_applied, *relaxation, M, c.coupling.tol, c.coupling.max_iterations);
  CouplingResult r = loop.run();
  if (!r.failure.empty()) throw SolverFailure(kWhat + r.failure);
  if (!r.converged)
    throw SolverFailure(std::string(kWhat) + "the coupling did not converge in coupling.max_iterations = " +
                        std::to_string(c.coupling.max_iterations) + " passes");
  SteadyCoupledStart start{r.structure, f.stokes->solution(), r.fluid_load, r.iterations};
  start.fluid.exact_on = nullptr;
  return start;
}

}  // namespace fsi
