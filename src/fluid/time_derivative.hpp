// The fluid's time derivative ρ_F ∂v/∂t on the fixed mesh by a backward
// differentiation formula (SPEC §12):
//     ρ (α v^{n+1} − β₁ v^n − β₂ v^{n−1}) / Δt,
// BDF1 (α, β₁, β₂) = (1, 1, 0) and BDF2 (3/2, 2, −1/2), tested with the mini space's
// functions, bubbles included. Its matrix is the mass with the coefficient ρα/Δt
// (add_mass, the penalty's own integrator) and the history its load, so the steady
// operator (Stokes, Navier–Stokes's Newton steps, the penalty) is unchanged beside it.
#pragma once

#include "fluid/mini_element.hpp"
#include "fluid/stokes_assembler.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

enum class TimeScheme { bdf1, bdf2 };

struct BdfWeights {
  double alpha = 1, beta1 = 1, beta2 = 0;
};
// The weights of the step after `steps_done` steps: BDF2 starts with one BDF1 step
// (it needs two past states), which keeps its global second order.
BdfWeights bdf_weights(TimeScheme scheme, int steps_done);

class FluidTimeDerivative final : public ElementTerm {
 public:
  FluidTimeDerivative(double rho, const Mesh& mesh) : rho_(rho), mesh_(mesh) {}

  // The next step's Δt, weights and past states (referenced, not copied; v_nm1 may be
  // null where beta2 = 0). The fluid's terms changed: PenalisedStokes::terms_changed().
  void set_step(double dt, const BdfWeights& weights, const FluidSolution& v_n, const FluidSolution* v_nm1);

  void add(int t, const P1Triangle& T, MiniLocal& e) const override;
  void add_load(int t, const P1Triangle& T, ElementLoad& load) const override;
  bool symmetric() const override { return true; }

 private:
  double rho_;
  const Mesh& mesh_;
  double dt_ = 1;
  BdfWeights weights_;
  const FluidSolution* v_n_ = nullptr;
  const FluidSolution* v_nm1_ = nullptr;
};

}  // namespace fsi
