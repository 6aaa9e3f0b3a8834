// The mini element (paper §4): velocity P1 + cubic bubble b = λ1λ2λ3, pressure P1,
// on one triangle, for
//     ∫ 2μ ε(v):ε(w) − ∫ (div w) p + κ ∫ v·w = ∫ f·w,   −∫ (div v) q = 0,
// with κ = χ_T/ε the penalty of the fictitious domain. Bubble integrals are exact
// (closed forms below). The local system is the sum of small integrators, one per
// term (viscous, divergence, a mass with a coefficient: the penalty now, ρ/Δt for
// time), and of any ElementTerm a solver adds (convection, SPEC §10). The two bubble
// unknowns are condensed statically, leaving a 9×9 matrix on the local dofs
// [v1 at 3 vertices, v2 at 3, p at 3], symmetric while every term is.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "fluid/viscous_form.hpp"

namespace fsi {

using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix29d = Eigen::Matrix<double, 2, 9>;
using Matrix92d = Eigen::Matrix<double, 9, 2>;

// Load integrals of one triangle, independent of χ: ∫ f·(λ_a e_c) and ∫ f_d b; and the
// continuity rows' right-hand side, ∫ g λ_a for −∫ (div v) q = ∫ g q (0 but where a
// term prescribes a dilatation: the structure's inside χ in time, SPEC §12).
struct ElementLoad {
  Eigen::Matrix<double, 6, 1> F_V = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector2d F_b = Eigen::Vector2d::Zero();
  Eigen::Vector3d F_P = Eigen::Vector3d::Zero();
};

// ElementLoad of f on T by `rule` (degree 6 for the cubic bubble times a smooth f).
ElementLoad element_load(const P1Triangle& T, const std::function<Point(const Point&)>& f,
                         const TriangleRule& rule);

// The local system before condensation, each integrator adding its term:
//   [M      E_col] [V; P]   [F_VP]
//   [E_row  A_bb ] [β]    = [F_b ]
// M = [A_VV  B_PVᵀ; B_PV  0] on [v1(3), v2(3), p(3)], β the bubble's two coefficients.
struct MiniLocal {
  Matrix9d M = Matrix9d::Zero();
  Eigen::Matrix2d A_bb = Eigen::Matrix2d::Zero();
  Matrix29d E_row = Matrix29d::Zero();  // the bubble's rows against [V; P]
  Matrix92d E_col = Matrix92d::Zero();  // [V; P]'s rows against the bubble
  bool symmetric = true;                // no term has broken the symmetry
};

// ∫ 2μ ε(v):ε(w). The bubble couples to no P1 velocity here (∇λ_a is constant on T
// and ∫_T ∇b = 0).
void add_viscous(const P1Triangle& T, double mu, MiniLocal& e);
// μ ∫ ∇v : ∇w, the gradient form (SPEC §10 fluid.viscous_form = "gradient": the DFG
// benchmark's do-nothing outflow is this form's natural condition). Equal to the
// symmetric form's ∫ 2μ ε:ε for divergence-free fields with v = 0 on the boundary,
// not at an outflow. The bubble couples to no P1 velocity here either.
void add_viscous_gradient(const P1Triangle& T, double mu, MiniLocal& e);
// −∫ (div w) p − ∫ (div v) q (with −∫ div(b e_d) q = ∫ b ∂_d q, b = 0 on ∂T).
void add_divergence(const P1Triangle& T, MiniLocal& e);
// κ ∫ v·w: the penalty χ_T/ε (eq. 25); ρ/Δt for a time step.
void add_mass(const P1Triangle& T, double kappa, MiniLocal& e);

// A further term of the momentum equation on triangle t (an Oseen or Newton
// convection term for Navier–Stokes): adds itself to e, and clears e.symmetric if its
// form is not symmetric (the solver paths that need symmetry then refuse the system).
class ElementTerm {
 public:
  virtual ~ElementTerm() = default;
  virtual void add(int t, const P1Triangle& T, MiniLocal& e) const = 0;
  virtual bool symmetric() const = 0;
  // Its part of triangle t's load (Newton's right-hand side of a linearised term);
  // none by default.
  virtual void add_load(int /*t*/, const P1Triangle& /*T*/, ElementLoad& /*load*/) const {}
};

// The Stokes terms with the penalty κ: viscous (in `form`), divergence, mass.
MiniLocal mini_local(const P1Triangle& T, double mu, double kappa, ViscousForm form = ViscousForm::symmetric);

// The bubble's own rows: A_bb β + E [V; P] = F_b.
struct BubbleBlock {
  Eigen::Matrix2d A_bb_inv;
  Matrix29d E;
};
BubbleBlock bubble_block(const P1Triangle& T, double mu, double kappa);
BubbleBlock bubble_block(const MiniLocal& e);

struct CondensedElement {
  Matrix9d K;    // M − E_col A_bb⁻¹ E_row
  Vector9d F;    // [F_V; F_P] − E_col A_bb⁻¹ F_b
};

CondensedElement condense(const MiniLocal& e, const ElementLoad& load);
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
