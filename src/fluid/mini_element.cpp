#include "fluid/mini_element.hpp"

#include <Eigen/LU>

namespace fsi {

CondensedElement condensed_mini_element(const P1Triangle& T, double mu, double kappa,
                                        const ElementLoad& load) {
  const double area = T.area;
  // M = [A_VV  B_PVᵀ; B_PV  0] on [v1(3), v2(3), p(3)].
  Matrix9d M = Matrix9d::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double gg = T.grad.row(a).dot(T.grad.row(b));
      const double mass = kappa * bubble::mass_p1(area, a, b);
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d)
          // 2μ ε(λ_a e_c):ε(λ_b e_d) = μ(δ_cd ∇λ_a·∇λ_b + ∂_d λ_a ∂_c λ_b)
          M(3 * c + a, 3 * d + b) =
              area * mu * ((c == d ? gg : 0.0) + T.grad(a, d) * T.grad(b, c)) + (c == d ? mass : 0.0);
    }
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) {
        const double b_kac = -T.grad(a, c) * area / 3.0;  // −∫ ∂_c λ_a q_k
        M(6 + k, 3 * c + a) = b_kac;
        M(3 * c + a, 6 + k) = b_kac;
      }

  const BubbleBlock bb = bubble_block(T, mu, kappa);
  CondensedElement out;
  out.K = M - bb.E.transpose() * bb.A_bb_inv * bb.E;
  out.F.setZero();
  out.F.head<6>() = load.F_V;
  out.F -= bb.E.transpose() * (bb.A_bb_inv * load.F_b);
  return out;
}

ElementLoad element_load(const P1Triangle& T, const std::function<Point(const Point&)>& f,
                         const TriangleRule& rule) {
  ElementLoad load;
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Eigen::Vector3d& l = rule.lambda[q];
    const Point fq = f(T.point(l)) * (rule.w[q] * T.area);
    for (int c = 0; c < 2; ++c) {
      for (int a = 0; a < 3; ++a) load.F_V[3 * c + a] += fq[c] * l[a];
      load.F_b[c] += fq[c] * bubble_value(l);
    }
  }
  return load;
}

BubbleBlock bubble_block(const P1Triangle& T, double mu, double kappa) {
  // The viscous term does not couple the bubble with P1 velocities (∇λ_a is
  // constant on T and ∫_T ∇b = 0): only the penalty mass and the divergence do.
  Eigen::Matrix2d A_bb;
  const double gg11 = bubble::grad_grad(T, 0, 0), gg22 = bubble::grad_grad(T, 1, 1);
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d)
      A_bb(c, d) = mu * ((c == d ? gg11 + gg22 : 0.0) + bubble::grad_grad(T, d, c)) +
                   (c == d ? kappa * bubble::bubble_squared(T.area) : 0.0);
  BubbleBlock out;
  out.E.setZero();
  for (int d = 0; d < 2; ++d) {
    for (int a = 0; a < 3; ++a) out.E(d, 3 * d + a) = kappa * bubble::p1_times_bubble(T.area);
    // −∫ div(b e_d) q_k = ∫ b ∂_d q_k (b = 0 on ∂T)
    for (int k = 0; k < 3; ++k) out.E(d, 6 + k) = T.grad(k, d) * bubble::bubble_integral(T.area);
  }
  out.A_bb_inv = A_bb.inverse();
  return out;
}

}  // namespace fsi
