// The fluid step with fluid.method = "body-fitted" (SPEC §5 steps 2–3): given u^k, the
// mesh of D \ φ^k(Ω_S0), Stokes with v = 0 on Γ_u, and the load by the residual method
// (body_fitted_fluid.hpp). The structure's answer must find no contact: the fluid
// between the structure and an obstacle cannot be body-fitted.
#pragma once

#include <string>

#include "coupling/body_fitted_fluid.hpp"
#include "coupling/coupled_map.hpp"

namespace fsi {

class BodyFittedStep final : public FluidStep {
 public:
  explicit BodyFittedStep(BodyFittedFluid& fluid) : fluid_(fluid) {}

  Eigen::VectorXd load(const Eigen::VectorXd& u, int k, IterationRecord& rec) override;
  // Refuses a structure in contact; else this pass's fluid becomes the last good one.
  void accept(const ContactSolution& structure, int k) override;
  std::string describe(const IterationRecord& rec) const override;

  // The fluid solve that produced the last accepted load (its mesh and fields), if any.
  const BodyFittedSolve* last() const { return last_.mesh ? &last_ : nullptr; }

 private:
  BodyFittedFluid& fluid_;
  BodyFittedSolve pass_, last_;
};

}  // namespace fsi
