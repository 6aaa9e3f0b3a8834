// The fluid step of the penalised fictitious domain (the paper, §6 steps 2–3): χ of
// φ^k(Ω_S0), the penalised Stokes solve (exact where the deformed vertices sample it:
// the fluid decides what that costs), and the force of eq. (33) at those vertices.
#pragma once

#include <functional>

#include "coupling/coupled_map.hpp"
#include "coupling/force_transfer.hpp"
#include "fluid/chi.hpp"
#include "fluid/penalised_stokes.hpp"

namespace fsi {

class PenalisedStep final : public FluidStep {
 public:
  struct Parts {
    const Mesh& structure;  // the structure's reference mesh (P1, or P2's nodal mesh)
    PenalisedStokes& fluid;
    const PointLocator& fluid_locator;
    const ChiComputer& chi;
    const FluidForce& force;
  };
  explicit PenalisedStep(Parts parts) : p_(parts) {}

  Eigen::VectorXd load(const Eigen::VectorXd& u, int k, IterationRecord& rec) override;
  std::string describe(const IterationRecord& rec) const override;

 private:
  Parts p_;
};

}  // namespace fsi
