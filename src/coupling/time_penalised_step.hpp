// The fluid's half of a pass in a coupled time step (SPEC §12): the penalised step of
// §5 (coupling/penalised_step.hpp) with the fluid marched in time. At the pass's state
// u (a candidate u^{n+1}):
//   χ of φ(Ω_S0); the structure's velocity by Newmark, ũ̇ = 2(u − u^n)/Δt − u̇^n, carried
//   to the fluid triangles' barycentres inside the deformed structure (the penalty's
//   load (1/ε) ∫ χ ũ̇·w, fluid/penalty_velocity.hpp); the fluid's step solved with the
//   history of FluidTimeStepper::begin, the fluid inside χ taking the structure's
//   dilatation (div v = χ div ũ̇: PenaltyVelocityLoad); and the fluid's force on the
//   structure as the penalty's reaction,
//       F_i = (1/ε) Σ_T χ_T ∫_T (v_h − ū_T)·w̃_i,
//   w̃_i the fluid-space interpolant of the structure's basis function φ_i, integrated
//   as the fluid's own mass term is. By the fluid's discrete momentum equation tested
//   with w̃_i, this is exactly its viscous, pressure, inertial and body-force terms on
//   w̃_i: the whole force of the fluid, in the fluid's own discretisation.
// Why not eq. (33) as the steady coupling: in time its (1/ε) ∫_{Ω_S0} (ṽ − ũ̇)·w, the
// fluid sampled at the structure's vertices, and its pressure term, on the structure's
// mesh, leave a residue of order 1/ε that the two meshes' quadratures do not cancel: a
// beam falling in a fluid of density and viscosity 1e-6 moved 0.9 % (5 % with the
// penalty sampled at the vertices) off the structure alone at ε = 1e-5; with this
// force it is 2e-5 (docs/validation.md, "The coupled time loop").
#pragma once

#include "coupling/coupled_map.hpp"
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
  Eigen::Matrix2Xd chi_velocity(const Eigen::VectorXd& chi, const Mesh& deformed, const Eigen::VectorXd& u_dot,
                                Eigen::VectorXd& chi_div);
  Eigen::VectorXd penalty_force(const FluidSolution& v, const Eigen::Matrix2Xd& chi_u) const;

  Parts p_;
  Eigen::VectorXd u_n_, v_n_;
  std::vector<Inside> inside_;  // the last pass's
  Eigen::VectorXd last_u_;      // the last pass's state
};

}  // namespace fsi
