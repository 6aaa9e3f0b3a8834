#include "coupling/fixed_point_loop.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "coupling/pass_steps.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

FixedPointLoop::FixedPointLoop(CoupledMap& H, Relaxation& relaxation, const SparseMatrix& M, double tol,
                               int max_iterations)
    : H_(H), relaxation_(relaxation), M_(M), tol_(tol), max_iterations_(max_iterations) {}

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
  Eigen::VectorXd u = initial_iterate(H_.structure().solver(), u0);
  const ContactSolution* warm = nullptr;
  const bool inexact = H_.structure().nonlinear();
  double last_move = 0;  // the last increment's largest dof (m)
  const Projection project = [this](const Eigen::VectorXd& z) { return H_.structure().project(z); };
  for (int k = 1; k <= max_iterations_; ++k) {
    result.iterations = k;
    IterationRecord rec;
    rec.iteration = k;
    const Pass pass{k, warm, inexact && k > 1 ? inexact_fraction * last_move : 0};
    MapValue value = H_(u, pass, rec);  // steps 2–4
    result.structure = std::move(value.structure);  // only a good state replaces the last one
    result.fluid_load = std::move(value.fluid_load);
    const Eigen::VectorXd d = result.structure.u - u;  // step 5
    rec.increment = std::sqrt(d.dot(M_ * d));
    last_move = d.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(rec.increment))
      throw SolverFailure("the stopping test failed at fixed-point iteration " + std::to_string(k) +
                          ": the increment is not a finite number");
    rec.active_nodes = result.structure.qp.active_count();
    if (observe) observe(result.structure.u, rec);
    result.final_increment = rec.increment;
    result.final_norm = std::sqrt(result.structure.u.dot(M_ * result.structure.u));
    const bool converged = rec.increment < tol_;
    if (converged && pass.newton_step_tol > 0 && value.load.size()) solve_exactly(result, value.load, k, rec);
    result.history.push_back(rec);  // recorded before relaxing: kept if that fails
    if (!converged && k < max_iterations_) u = relaxed_iterate(relaxation_, project, u, result.structure.u, k, rec, result);
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
      if (progress)
        progress(std::string("[coupling] interrupted (") + interrupt_signal_name() + "): stopping after iteration " +
                 std::to_string(k));
      return;
    }
    warm = &result.structure;
  }
}

// The converged pass's structure again, from its inexact state, to Newton's full
// tolerance: the state and the residual the run reports (SPEC §11).
void FixedPointLoop::solve_exactly(CouplingResult& result, const Eigen::VectorXd& load, int k, IterationRecord& rec) {
  const Stopwatch clock;
  ContactSolution exact =
      guarded("the contact QP", k, [&] { return H_.structure().solve_again(load, result.structure); });
  if (!exact.u.allFinite()) throw SolverFailure("the contact QP failed at fixed-point iteration " + std::to_string(k) +
                                                ": non-finite displacement");
  rec.newton_steps += exact.newton.steps;
  rec.t_structure += clock.elapsed();
  result.structure = std::move(exact);
}

}  // namespace fsi
