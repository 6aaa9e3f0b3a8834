#include "coupling/fixed_point_loop.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "coupling/pass_steps.hpp"

namespace fsi {

FixedPointLoop::FixedPointLoop(CoupledMap& H, Relaxation& relaxation, const SparseMatrix& M, double tol,
                               int max_iterations)
    : H_(H), relaxation_(relaxation), M_(M), tol_(tol), max_iterations_(max_iterations) {
  relaxation_.project = [this](const Eigen::VectorXd& z) { return H_.structure().project(z); };
}

CouplingResult FixedPointLoop::run(const Eigen::VectorXd& u0) {
  CouplingResult result;
  result.structure = H_.structure().at_rest();  // the last good state if the first pass fails
  try {
    iterate(result, u0);
  } catch (const SolverFailure& e) {
    result.failure = e.what();
  }
  result.projections = relaxation_.projections();
  return result;
}

void FixedPointLoop::iterate(CouplingResult& result, const Eigen::VectorXd& u0) {
  Eigen::VectorXd u = initial_iterate(H_.structure(), u0);
  const ContactSolution* warm = nullptr;
  for (int k = 1; k <= max_iterations_; ++k) {
    result.iterations = k;
    IterationRecord rec;
    rec.iteration = k;
    MapValue value = H_(u, k, warm, rec);  // steps 2–4
    result.structure = std::move(value.structure);  // only a good state replaces the last one
    result.fluid_load = std::move(value.fluid_load);
    const Eigen::VectorXd d = result.structure.u - u;  // step 5
    rec.increment = std::sqrt(d.dot(M_ * d));
    if (!std::isfinite(rec.increment))
      throw SolverFailure("the stopping test failed at fixed-point iteration " + std::to_string(k) +
                          ": the increment is not a finite number");
    rec.active_nodes = result.structure.qp.active_count();
    if (observe) observe(result.structure.u, rec);
    result.final_increment = rec.increment;
    result.final_norm = std::sqrt(result.structure.u.dot(M_ * result.structure.u));
    const bool converged = rec.increment < tol_;
    result.history.push_back(rec);  // recorded before relaxing: kept if that fails
    if (!converged && k < max_iterations_) u = relaxed_iterate(relaxation_, u, result.structure.u, k, rec, result);
    if (progress) {
      char omega[16] = "-";
      if (std::isfinite(rec.omega)) std::snprintf(omega, sizeof omega, "%.3g", rec.omega);
      char line[96];
      std::snprintf(line, sizeof line, "[coupling] it %3d: increment %.4e  omega %-6s ", k, rec.increment, omega);
      progress(line + H_.describe(rec));
    }
    if (converged) {
      result.converged = true;
      return;
    }
    if (interrupt_requested()) {
      result.interrupted = true;
      if (progress) progress("[coupling] interrupted (Ctrl-C): stopping after iteration " + std::to_string(k));
      return;
    }
    warm = &result.structure;
  }
}

}  // namespace fsi
