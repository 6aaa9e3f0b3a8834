#include "coupling/coupled_map.hpp"

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {
namespace {

[[noreturn]] void fail(const std::string& phase, int k, const std::string& what) {
  throw SolverFailure(phase + " failed at fixed-point iteration " + std::to_string(k) + ": " + what);
}

}  // namespace

MapValue ComposedMap::operator()(const Eigen::VectorXd& u, const Pass& pass, IterationRecord& rec) {
  const int k = pass.k;
  MapValue value;
  value.load = b_applied_ + fluid_.load(u, k, rec);  // b_S (eq. 16 with the fluid's terms)
  if (!value.load.allFinite()) fail("the force transfer", k, "non-finite load on the structure");
  const Stopwatch clock;  // step 4: the contact QP, warm-started
  value.structure = guarded("the contact QP", k, [&] {
    return structure_.solve(value.load, u, pass.warm, pass.newton_step_tol);
  });
  if (!value.structure.u.allFinite()) fail("the contact QP", k, "non-finite displacement");
  fluid_.accept(value.structure, k);
  value.fluid_load = value.load - b_applied_;
  rec.newton_steps = value.structure.newton.steps;
  rec.t_structure = clock.elapsed();
  return value;
}

}  // namespace fsi
