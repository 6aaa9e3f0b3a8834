#include "fluid/penalty_velocity.hpp"

#include <stdexcept>

namespace fsi {

void PenaltyVelocityLoad::set(Eigen::Matrix2Xd chi_velocity, Eigen::VectorXd chi_dilatation) {
  if (chi_velocity.cols() != chi_velocity_.cols() ||
      (chi_dilatation.size() && chi_dilatation.size() != chi_velocity.cols()))
    throw std::invalid_argument("PenaltyVelocityLoad::set: one velocity (and dilatation) per fluid triangle");
  chi_velocity_ = std::move(chi_velocity);
  chi_dilatation_ = std::move(chi_dilatation);
}

void PenaltyVelocityLoad::add_load(int t, const P1Triangle& T, ElementLoad& load) const {
  if (chi_dilatation_.size() && chi_dilatation_[t] != 0)  // −∫ (div v) q = −∫ χ div ū q
    load.F_P -= Eigen::Vector3d::Constant(chi_dilatation_[t] * T.area / 3);
  const Eigen::Vector2d u = chi_velocity_.col(t) / eps_;
  if (u.isZero(0.0)) return;
  for (int c = 0; c < 2; ++c) {
    for (int a = 0; a < 3; ++a) load.F_V[3 * c + a] += u[c] * T.area / 3;
    load.F_b[c] += u[c] * T.area / 60;
  }
}

}  // namespace fsi
