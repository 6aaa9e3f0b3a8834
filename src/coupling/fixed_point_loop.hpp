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
#include "solid/elasticity.hpp"

namespace fsi {

class FixedPointLoop {
 public:
  // M: the L²(Ω_S0) mass matrix of the stopping test (and the relaxation's).
  FixedPointLoop(CoupledMap& H, Relaxation& relaxation, const SparseMatrix& M, double tol, int max_iterations);
  ~FixedPointLoop() { relaxation_.project = nullptr; }  // it pointed at H's structure
  FixedPointLoop(const FixedPointLoop&) = delete;
  FixedPointLoop& operator=(const FixedPointLoop&) = delete;

  std::function<void(const std::string&)> progress;  // one line per pass
  PassObserver observe;                              // optional, each pass's ũ

  // From u0 (empty: the structure at rest; else projected onto the feasible set). Never
  // throws for a failed solve: it stops, keeps the last good state and says why in
  // CouplingResult::failure. A bug (std::logic_error, ...) propagates.
  CouplingResult run(const Eigen::VectorXd& u0);

 private:
  void iterate(CouplingResult& result, const Eigen::VectorXd& u0);

  CoupledMap& H_;
  Relaxation& relaxation_;
  const SparseMatrix& M_;
  double tol_;
  int max_iterations_;
};

}  // namespace fsi
