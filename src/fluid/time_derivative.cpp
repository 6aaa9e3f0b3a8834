#include "fluid/time_derivative.hpp"

#include <stdexcept>

namespace fsi {

BdfWeights bdf_weights(TimeScheme scheme, int steps_done) {
  if (scheme == TimeScheme::bdf2 && steps_done >= 1) return {1.5, 2.0, -0.5};
  return {1.0, 1.0, 0.0};
}

void FluidTimeDerivative::set_step(double dt, const BdfWeights& weights, const FluidSolution& v_n,
                                   const FluidSolution* v_nm1) {
  if (!(dt > 0)) throw std::invalid_argument("FluidTimeDerivative: the time step must be positive");
  if (weights.beta2 != 0 && v_nm1 == nullptr)
    throw std::invalid_argument("FluidTimeDerivative: BDF2 needs the state before the last");
  dt_ = dt, weights_ = weights, v_n_ = &v_n, v_nm1_ = v_nm1;
}

void FluidTimeDerivative::add(int, const P1Triangle& T, MiniLocal& e) const {
  add_mass(T, rho_ * weights_.alpha / dt_, e);
}

// (ρ/Δt) ∫ (β₁ v^n + β₂ v^{n−1})·φ: the local mass (add_mass with coefficient 1) applied
// to the history's coefficients.
void FluidTimeDerivative::add_load(int t, const P1Triangle& T, ElementLoad& load) const {
  if (v_n_ == nullptr) throw std::logic_error("FluidTimeDerivative: assembled before set_step");
  Eigen::Matrix<double, 8, 1> u = weights_.beta1 * velocity_coefficients(mesh_, *v_n_, t);
  if (weights_.beta2 != 0) u += weights_.beta2 * velocity_coefficients(mesh_, *v_nm1_, t);
  MiniLocal mass;
  add_mass(T, rho_ / dt_, mass);
  load.F_V += mass.M.topLeftCorner<6, 6>() * u.head<6>() + mass.E_col.topRows<6>() * u.tail<2>();
  load.F_b += mass.E_row.leftCols<6>() * u.head<6>() + mass.A_bb * u.tail<2>();
}

}  // namespace fsi
