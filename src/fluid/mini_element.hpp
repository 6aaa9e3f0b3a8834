// The mini element (paper §4): velocity P1 + cubic bubble b = λ1λ2λ3, pressure P1,
// on one triangle, for
//     ∫ 2μ ε(v):ε(w) − ∫ (div w) p + κ ∫ v·w = ∫ f·w,   −∫ (div v) q = 0,
// with κ = χ_T/ε the penalty of the fictitious domain. Bubble integrals are exact
// (closed forms below). The two bubble unknowns are condensed statically, leaving
// a symmetric 9×9 matrix on the local dofs [v1 at 3 vertices, v2 at 3, p at 3].
#pragma once

#include <Eigen/Core>
#include <functional>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"

namespace fsi {

using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix29d = Eigen::Matrix<double, 2, 9>;

// Load integrals of one triangle, independent of χ: ∫ f·(λ_a e_c) and ∫ f_d b.
struct ElementLoad {
  Eigen::Matrix<double, 6, 1> F_V = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector2d F_b = Eigen::Vector2d::Zero();
};

// ElementLoad of f on T by `rule` (degree 6 for the cubic bubble times a smooth f).
ElementLoad element_load(const P1Triangle& T, const std::function<Point(const Point&)>& f,
                         const TriangleRule& rule);

// The bubble's own rows: A_bb β + E [V; P] = F_b.
struct BubbleBlock {
  Eigen::Matrix2d A_bb_inv;
  Matrix29d E;
};
BubbleBlock bubble_block(const P1Triangle& T, double mu, double kappa);

struct CondensedElement {
  Matrix9d K;    // M − Eᵀ A_bb⁻¹ E
  Vector9d F;    // [F_V; 0] − Eᵀ A_bb⁻¹ F_b
};

CondensedElement condensed_mini_element(const P1Triangle& T, double mu, double kappa,
                                        const ElementLoad& load);

// Closed-form integrals on T (|T| = area), used above and checked against
// quadrature in tests/fluid/mini_element_test.cpp:
//   ∫ λ_a λ_b = |T|(1+δ_ab)/12, ∫ λ_a b = |T|/180, ∫ b² = |T|/2520, ∫ b = |T|/60,
//   ∫ ∂_c b ∂_d b = |T|/180 · G_c·G_d  with G_c = (∂_c λ_1, ∂_c λ_2, ∂_c λ_3).
namespace bubble {
inline double mass_p1(double area, int a, int b) { return area * (a == b ? 2.0 : 1.0) / 12.0; }
inline double p1_times_bubble(double area) { return area / 180.0; }
inline double bubble_squared(double area) { return area / 2520.0; }
inline double bubble_integral(double area) { return area / 60.0; }
inline double grad_grad(const P1Triangle& T, int c, int d) {
  return T.area / 180.0 * T.grad.col(c).dot(T.grad.col(d));
}
}  // namespace bubble

// Value of the bubble at barycentric coordinates λ, and its gradient.
inline double bubble_value(const Eigen::Vector3d& l) { return l[0] * l[1] * l[2]; }
inline Eigen::Vector2d bubble_gradient(const P1Triangle& T, const Eigen::Vector3d& l) {
  return (l[1] * l[2] * T.grad.row(0) + l[0] * l[2] * T.grad.row(1) + l[0] * l[1] * T.grad.row(2))
      .transpose();
}

}  // namespace fsi
