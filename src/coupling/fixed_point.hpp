// The paper's fixed-point algorithm (§6, SPEC §5): given u^k,
//   χ from φ^k(Ω_S0) → fluid solve → force (eq. 33) → contact QP → ũ^{k+1},
//   stop if ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)} < tol, else u^{k+1} = relaxation(u^k, ũ^{k+1}):
// FixedPointLoop (fixed_point_loop.hpp) around the map H of the penalised fluid
// (PenalisedMap, penalised_map.hpp). The pieces it calls are built once by the caller.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "coupling/coupling_result.hpp"
#include "coupling/fixed_point_loop.hpp"
#include "coupling/penalised_map.hpp"
#include "coupling/relaxation.hpp"

namespace fsi {

class FixedPointCoupling {
 public:
  using Parts = PenalisedMap::Parts;
  FixedPointCoupling(Parts parts, Relaxation& relaxation, double tol, int max_iterations);

  // One line per iteration (for stderr).
  std::function<void(const std::string&)> progress;
  PassObserver observe;  // optional: FixedPointLoop::observe
  // Called with u^k before each pass's QP: contact.gap = "normal" re-linearises the
  // constraint about the current state there, once per pass (SPEC §9). Empty: the
  // constraint stays as built (the paper's eq. 15).
  std::function<void(const Eigen::VectorXd& u)> relinearise;
  // u⁰ instead of the structure at rest (2nv, feasible: another run's ũ, say). A
  // restart from another scheme's end state tells whether that state is a fixed
  // point for this scheme too (study/converge.cpp).
  Eigen::VectorXd initial;
  double inexact_fraction = kInexactNewtonFraction;  // FixedPointLoop's (0: exact Newton every pass)

  // Never throws for a failed solve: it stops, keeps the last good state and says
  // why in CouplingResult::failure (a SolverFailure or QpError in a phase, memory
  // running out, or a field became non-finite). A bug (std::logic_error,
  // std::invalid_argument, ... from our own code) is not a failed solve: it propagates.
  CouplingResult run();

 private:
  Parts p_;
  Relaxation& relaxation_;
  double tol_;
  int max_iterations_;
  SparseMatrix M_;  // L²(Ω_S0) mass, for the stopping test
};

}  // namespace fsi
