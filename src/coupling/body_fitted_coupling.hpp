// The fixed point of §6 with the body-fitted fluid step (fluid.method = "body-fitted"):
// given u^k,
//   mesh of D \ φ^k(Ω_S0) → Stokes, v = 0 on Γ_u → load by the residual method
//   (body_fitted_fluid.hpp) → contact QP → ũ^{k+1},
// stop if ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)} < tol, else u^{k+1} = relaxation(u^k, ũ^{k+1}):
// FixedPointLoop (fixed_point_loop.hpp) around this fluid's map H, as FixedPointCoupling
// around the penalised one (χ, the penalised solve, eq. 33). A pass whose QP
// finds contact is refused: the fluid between the structure and an obstacle
// cannot be body-fitted.
#pragma once

#include <functional>
#include <string>

#include "coupling/body_fitted_fluid.hpp"
#include "coupling/fixed_point.hpp"

namespace fsi {

class BodyFittedCoupling {
 public:
  struct Parts {
    ElasticContactSolver& structure;
    const Eigen::VectorXd& b_applied;  // f_S and h_N part of b_S
    BodyFittedFluid& fluid;
    Relaxation& relaxation;
  };
  BodyFittedCoupling(Parts parts, double tol, int max_iterations);

  std::function<void(const std::string&)> progress;  // one line per pass
  PassObserver observe;                              // optional: FixedPointLoop::observe
  // u⁰ instead of the structure at rest, as FixedPointCoupling::initial.
  Eigen::VectorXd initial;
  // contact.gap = "normal" (SPEC §9): the constraint moved to the pass's u before its
  // QP, as FixedPointCoupling::relinearise. The QP must still find no contact.
  std::function<void(const Eigen::VectorXd& u)> relinearise;

  // As FixedPointCoupling::run: a failed phase stops the loop and is named in
  // CouplingResult::failure; the last good state is kept.
  CouplingResult run();

  // The fluid step that produced the result's load (its mesh and fields), if any.
  const BodyFittedStep* last_fluid() const { return last_fluid_.mesh ? &last_fluid_ : nullptr; }

 private:
  Parts p_;
  double tol_;
  int max_iterations_;
  SparseMatrix M_;  // L²(Ω_S0) mass, for the stopping test
  BodyFittedStep last_fluid_;
};

}  // namespace fsi
