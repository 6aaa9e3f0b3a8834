// The fluid's half of a pass in a coupled time step (SPEC §12): the penalised step of
// §5 (coupling/penalised_step.hpp) with the fluid marched in time. At the pass's state
// u (a candidate u^{n+1}):
//   χ of φ(Ω_S0); the structure's velocity by Newmark, ũ̇ = 2(u − u^n)/Δt − u̇^n, carried
//   to the fluid triangles' barycentres inside the deformed structure (the penalty's
//   load (1/ε) ∫ χ ũ̇·w, fluid/penalty_velocity.hpp); the fluid's step solved with the
//   history of FluidTimeStepper::begin; and the load: eq. (33)'s viscous, pressure and
//   body-force terms, the fictitious fluid's inertia ρ_F ∫ ∂ṽ/∂t·w (the BDF derivative
//   at the deformed sample points), and the penalty's force as the fluid feels it,
//       (1/ε) Σ_T χ_T |T| (v_h(x_T) − ū_T)·w(X_T)   (x_T the barycentre, X_T its
//       reference point; one point per fluid triangle, where χ and ū are sampled),
//   instead of eq. (33)'s (1/ε) ∫_{Ω_S0} ṽ·w. Why: in time ṽ − ũ̇ at the structure's
//   boundary vertices, half outside χ, is O(ũ̇) and the 1/ε made it a spurious force,
//   measured at 5 % of a falling beam's weight with a fluid of density and viscosity
//   1e-6 (docs/validation.md); the fluid-side sum is the penalty's own reaction and
//   vanishes with the fluid. The convection inside the structure, ρ_F (ṽ·∇)ṽ, is left
//   out, as in the steady coupling (the fluid there moves with the structure).
#pragma once

#include "coupling/coupled_map.hpp"
#include "coupling/force_transfer.hpp"
#include "fluid/chi.hpp"
#include "fluid/fluid_time_stepper.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fluid/penalty_velocity.hpp"

namespace fsi {

class TimePenalisedStep final : public FluidStep {
 public:
  struct Parts {
    const Mesh& structure;  // the structure's reference mesh (P1, or P2's nodal mesh)
    PenalisedStokes& fluid;
    FluidTimeStepper& stepper;
    PenaltyVelocityLoad& penalty;  // added to `fluid` by the caller
    const PointLocator& fluid_locator;
    const ChiComputer& chi;
    const FluidForce& force;
    double rho;  // ρ_F
  };
  explicit TimePenalisedStep(Parts parts) : p_(parts) {}

  // The step's start: the structure's u^n, u̇^n (all dofs), after FluidTimeStepper::begin.
  void begin_step(const Eigen::VectorXd& u_n, const Eigen::VectorXd& v_n);
  // ũ̇ of a candidate u^{n+1} (Newmark's average acceleration).
  Eigen::VectorXd velocity(const Eigen::VectorXd& u) const;

  Eigen::VectorXd load(const Eigen::VectorXd& u, int k, IterationRecord& rec) override;
  std::string describe(const IterationRecord& rec) const override;

 private:
  // Where a fluid triangle with χ > 0 has its barycentre in the deformed structure.
  struct Inside {
    int fluid = -1;     // the fluid triangle
    double chi = 0;     // its χ
    Location at;        // in the deformed (= reference) structure's triangles
  };
  Eigen::Matrix2Xd chi_velocity(const Eigen::VectorXd& chi, const Mesh& deformed, const Eigen::VectorXd& u_dot);
  Eigen::VectorXd penalty_force(const FluidSolution& v, const Eigen::Matrix2Xd& chi_u) const;
  Eigen::VectorXd inertia_at(const std::vector<Location>& where, const FluidSolution& v_next) const;

  Parts p_;
  Eigen::VectorXd u_n_, v_n_;
  std::vector<Inside> inside_;  // the last pass's
};

}  // namespace fsi
