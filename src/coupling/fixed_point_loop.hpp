// The fixed-point loop of §6 around any coupled map H (coupling/coupled_map.hpp):
//   ũ^{k+1} = H(u^k); stop if ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)} < tol, else
//   u^{k+1} = relaxation(u^k, ũ^{k+1});
// the records, the stopping test, the relaxation's failure messages and Ctrl-C, written
// once for the penalised and the body-fitted fluid.
#pragma once

#include <functional>
#include <string>

#include "coupling/coupled_map.hpp"
#include "coupling/coupling_result.hpp"
#include "coupling/relaxation.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

// Inexact Newton for a nonlinear structure: from the second pass on, Newton stops once
// a step moves no dof by more than this fraction of the last increment's largest (the
// error left is below it: the convergence is quadratic), and the converged pass is
// solved again to the full residual tolerance. Its iterates then differ from exact
// solves by at most 1 % of what the fixed point still changes. Measured on the §7.2
// beam (SVK): 3–4 Newton steps a pass became 2, and a pass's structure + transfer went
// from 3.2× a linear pass's to 2.3× (docs/validation.md, "Cost").
inline constexpr double kInexactNewtonFraction = 0.01;

class FixedPointLoop {
 public:
  // M: the L²(Ω_S0) mass matrix of the stopping test (and the relaxation's).
  FixedPointLoop(CoupledMap& H, Relaxation& relaxation, const SparseMatrix& M, double tol, int max_iterations);
  FixedPointLoop(const FixedPointLoop&) = delete;
  FixedPointLoop& operator=(const FixedPointLoop&) = delete;

  std::function<void(const std::string&)> progress;  // one line per pass
  PassObserver observe;                              // optional, each pass's ũ
  double inexact_fraction = kInexactNewtonFraction;  // 0: Newton to its full tolerance every pass

  // From u0 (empty: the structure at rest; else projected onto the feasible set). Never
  // throws for a failed solve: it stops, keeps the last good state and says why in
  // CouplingResult::failure. A bug (std::logic_error, ...) propagates.
  CouplingResult run(const Eigen::VectorXd& u0);

 private:
  void iterate(CouplingResult& result, const Eigen::VectorXd& u0);
  void solve_exactly(CouplingResult& result, const Eigen::VectorXd& load, int k, IterationRecord& rec);

  CoupledMap& H_;
  Relaxation& relaxation_;
  const SparseMatrix& M_;
  double tol_;
  int max_iterations_;
};

}  // namespace fsi
