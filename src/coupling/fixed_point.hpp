// The paper's fixed-point algorithm (§6, SPEC §5) for any fluid step and the structure
// step: given u^k,
//   fluid step (χ of φ^k(Ω_S0) → penalised solve → eq. (33); or the body-fitted fluid)
//   → contact QP → ũ^{k+1},
//   stop if ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)} < tol, else u^{k+1} = relaxation(u^k, ũ^{k+1}):
// FixedPointLoop (fixed_point_loop.hpp) around H = structure step ∘ fluid step
// (ComposedMap, coupled_map.hpp), with any relaxation (preCICE's shape: the loop does
// not know which fluid, gap, material or relaxation it holds). One run() is one window;
// a time loop will call next_window from each step's converged state. The pieces it
// calls are built once by the caller.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "coupling/coupling_result.hpp"
#include "coupling/fixed_point_loop.hpp"
#include "coupling/coupled_map.hpp"
#include "fem/vector_p1.hpp"
#include "coupling/relaxation.hpp"

namespace fsi {

class FixedPointCoupling {
 public:
  // b_applied: f_S and h_N part of b_S (eq. 16). M: the L²(Ω_S0) mass matrix of the
  // stopping test, the one the relaxation was made with (assembled once, by the caller).
  FixedPointCoupling(FluidStep& fluid, StructureStep& structure, const Eigen::VectorXd& b_applied,
                     Relaxation& relaxation, const SparseMatrix& M, double tol, int max_iterations);

  // One line per iteration (for stderr).
  std::function<void(const std::string&)> progress;
  PassObserver observe;  // optional: FixedPointLoop::observe
  // u⁰ instead of the structure at rest (2nv, feasible: another run's ũ, say). A
  // restart from another scheme's end state tells whether that state is a fixed
  // point for this scheme too (study/converge.cpp).
  Eigen::VectorXd initial;
  double inexact_fraction = kInexactNewtonFraction;  // FixedPointLoop's (0: exact Newton every pass)

  // The first window, from `initial` (empty: rest) and the structure's linearisation at
  // rest. Never throws for a failed solve: it stops, keeps the last good state and says
  // why in CouplingResult::failure (a SolverFailure or QpError in a phase, memory
  // running out, or a field became non-finite). A bug (std::logic_error,
  // std::invalid_argument, ... from our own code) is not a failed solve: it propagates.
  CouplingResult run();
  // The next window (a time step), from u_start (the last window's ũ): the
  // relaxation's window ends first (IQN-ILS keeps its secant pairs: coupling.reuse).
  CouplingResult next_window(const Eigen::VectorXd& u_start);

 private:
  CouplingResult window(const Eigen::VectorXd& u0);

  ComposedMap H_;
  Relaxation& relaxation_;
  double tol_;
  int max_iterations_;
  const SparseMatrix& M_;
};

}  // namespace fsi
