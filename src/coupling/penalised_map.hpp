// H for the penalised fictitious domain (the paper, §6 steps 2–4): χ of φ^k(Ω_S0), the
// penalised Stokes solve (exact where the deformed vertices sample it: the fluid
// decides what that costs), the force of eq. (33) at those vertices, the contact QP.
#pragma once

#include <functional>

#include "coupling/coupled_map.hpp"
#include "coupling/force_transfer.hpp"
#include "fluid/chi.hpp"
#include "fluid/penalised_stokes.hpp"

namespace fsi {

class PenalisedMap final : public CoupledMap {
 public:
  struct Parts {
    ElasticContactSolver& structure;
    const Eigen::VectorXd& b_applied;  // f_S and h_N part of b_S
    PenalisedStokes& fluid;
    const PointLocator& fluid_locator;
    const ChiComputer& chi;
    const FluidForce& force;
  };
  explicit PenalisedMap(Parts parts) : p_(parts) {}

  // Called with u^k before the pass's QP (contact.gap = "normal" re-linearises there).
  std::function<void(const Eigen::VectorXd& u)> relinearise;

  MapValue operator()(const Eigen::VectorXd& u, int k, const ContactSolution* warm, IterationRecord& rec) override;
  std::string describe(const IterationRecord& rec) const override;
  ElasticContactSolver& structure() override { return p_.structure; }

 private:
  Parts p_;
};

}  // namespace fsi
