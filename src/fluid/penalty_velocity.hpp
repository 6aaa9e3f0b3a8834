// The structure's velocity in the penalty (SPEC §12): in time the penalty drives the
// fluid towards the structure's velocity, (1/ε) ∫ χ (v − ũ̇)·w, and the steady operator
// holds (1/ε) ∫ χ v·w already: this term is the load (1/ε) ∫ χ ũ̇·w. ũ̇ is taken
// constant on each fluid triangle, its value at the triangle's barycentre (where the
// barycentre rule samples χ): ū_T. Exact on the mini space: ∫ λ_a = |T|/3, ∫ b = |T|/60.
// And the structure's dilatation: inside χ the fluid takes div v = χ div ũ̇ instead of
// 0 (the load −∫ χ div ũ̇ q of the continuity rows), or else the incompressible fluid
// the penalty holds inside a compressible structure would resist its change of volume
// with a force of order 1/ε (measured: docs/validation.md, "The coupled time loop").
#pragma once

#include <Eigen/Core>

#include "fluid/mini_element.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

class PenaltyVelocityLoad final : public ElementTerm {
 public:
  PenaltyVelocityLoad(int triangles, double eps) : chi_velocity_(Eigen::Matrix2Xd::Zero(2, triangles)), eps_(eps) {}

  // χ_T ū_T per fluid triangle (2 × triangles; zero where χ = 0) and χ_T div ū_T (empty:
  // none). The fluid's terms changed: PenalisedStokes::terms_changed().
  void set(Eigen::Matrix2Xd chi_velocity, Eigen::VectorXd chi_dilatation = {});
  const Eigen::Matrix2Xd& chi_velocity() const { return chi_velocity_; }

  void add(int, const P1Triangle&, MiniLocal&) const override {}  // a load only
  void add_load(int t, const P1Triangle& T, ElementLoad& load) const override;
  bool symmetric() const override { return true; }

 private:
  Eigen::Matrix2Xd chi_velocity_;
  Eigen::VectorXd chi_dilatation_;
  double eps_;
};

}  // namespace fsi
