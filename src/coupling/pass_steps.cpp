#include "coupling/pass_steps.hpp"

#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

Eigen::VectorXd initial_iterate(ElasticContactSolver& structure, const Eigen::VectorXd& initial) {
  const Eigen::Index n = 2 * structure.mesh().num_vertices();
  if (initial.size() == 0) return Eigen::VectorXd::Zero(n);  // u⁰ = 0: feasible at rest
  if (initial.size() != n || !initial.allFinite())
    throw std::invalid_argument("the initial displacement does not fit the structure's mesh");
  return structure.project(initial);
}

Eigen::VectorXd relaxed_iterate(Relaxation& relaxation, const Projection& project, const Eigen::VectorXd& u,
                                const Eigen::VectorXd& u_tilde, int k, IterationRecord& rec, CouplingResult& result) {
  const std::string phase = "the relaxation (" + relaxation.name() + ")";
  Eigen::VectorXd next = guarded(phase, k, [&] { return relaxation.next(u, u_tilde, project); });
  if (!next.allFinite())
    throw SolverFailure(phase + " failed at fixed-point iteration " + std::to_string(k) + ": non-finite iterate");
  rec.omega = result.history.back().omega = relaxation.omega();
  return next;
}

}  // namespace fsi
