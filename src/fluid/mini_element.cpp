#include "fluid/mini_element.hpp"

#include <Eigen/LU>

namespace fsi {

void add_viscous(const P1Triangle& T, double mu, MiniLocal& e) {
  const double area = T.area;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double gg = T.grad.row(a).dot(T.grad.row(b));
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d)
          // 2μ ε(λ_a e_c):ε(λ_b e_d) = μ(δ_cd ∇λ_a·∇λ_b + ∂_d λ_a ∂_c λ_b)
          e.M(3 * c + a, 3 * d + b) += area * mu * ((c == d ? gg : 0.0) + T.grad(a, d) * T.grad(b, c));
    }
  const double gg11 = bubble::grad_grad(T, 0, 0), gg22 = bubble::grad_grad(T, 1, 1);
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d) e.A_bb(c, d) += mu * ((c == d ? gg11 + gg22 : 0.0) + bubble::grad_grad(T, d, c));
}

void add_viscous_gradient(const P1Triangle& T, double mu, MiniLocal& e) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double gg = T.area * mu * T.grad.row(a).dot(T.grad.row(b));  // μ ∫ ∇λ_a·∇λ_b
      for (int c = 0; c < 2; ++c) e.M(3 * c + a, 3 * c + b) += gg;
    }
  const double bb = mu * (bubble::grad_grad(T, 0, 0) + bubble::grad_grad(T, 1, 1));  // μ ∫ ∇b·∇b
  for (int c = 0; c < 2; ++c) e.A_bb(c, c) += bb;
}

void add_divergence(const P1Triangle& T, MiniLocal& e) {
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) {
        const double b_kac = -T.grad(a, c) * T.area / 3.0;  // −∫ ∂_c λ_a q_k
        e.M(6 + k, 3 * c + a) += b_kac;
        e.M(3 * c + a, 6 + k) += b_kac;
      }
  for (int d = 0; d < 2; ++d)
    for (int k = 0; k < 3; ++k) {  // −∫ div(b e_d) q_k = ∫ b ∂_d q_k (b = 0 on ∂T)
      const double b_dk = T.grad(k, d) * bubble::bubble_integral(T.area);
      e.E_row(d, 6 + k) += b_dk;
      e.E_col(6 + k, d) += b_dk;
    }
}

void add_mass(const P1Triangle& T, double kappa, MiniLocal& e) {
  const double area = T.area;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double mass = kappa * bubble::mass_p1(area, a, b);
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d) e.M(3 * c + a, 3 * d + b) += (c == d ? mass : 0.0);
    }
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d) e.A_bb(c, d) += (c == d ? kappa * bubble::bubble_squared(area) : 0.0);
  for (int d = 0; d < 2; ++d)
    for (int a = 0; a < 3; ++a) {
      const double m = kappa * bubble::p1_times_bubble(area);
      e.E_row(d, 3 * d + a) += m;
      e.E_col(3 * d + a, d) += m;
    }
}

MiniLocal mini_local(const P1Triangle& T, double mu, double kappa, ViscousForm form) {
  MiniLocal e;
  if (form == ViscousForm::symmetric)
    add_viscous(T, mu, e);
  else
    add_viscous_gradient(T, mu, e);
  add_mass(T, kappa, e);
  add_divergence(T, e);
  return e;
}

BubbleBlock bubble_block(const MiniLocal& e) {
  return {e.A_bb.inverse(), e.E_row};
}

BubbleBlock bubble_block(const P1Triangle& T, double mu, double kappa) {
  return bubble_block(mini_local(T, mu, kappa));
}

CondensedElement condense(const MiniLocal& e, const ElementLoad& load) {
  const Eigen::Matrix2d A_bb_inv = e.A_bb.inverse();
  CondensedElement out;
  out.K = e.M - e.E_col * A_bb_inv * e.E_row;
  out.F.setZero();
  out.F.head<6>() = load.F_V;
  out.F.tail<3>() = load.F_P;
  out.F -= e.E_col * (A_bb_inv * load.F_b);
  return out;
}

CondensedElement condensed_mini_element(const P1Triangle& T, double mu, double kappa,
                                        const ElementLoad& load) {
  return condense(mini_local(T, mu, kappa), load);
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

}  // namespace fsi
