#include "fluid/convection.hpp"

#include "fem/quadrature.hpp"

namespace fsi {
namespace {

// w's 8 coefficients on triangle t in the basis order of mini_velocity_basis.
Eigen::Matrix<double, 8, 1> local_coefficients(const Mesh& mesh, const FluidSolution& w, int t) {
  Eigen::Matrix<double, 8, 1> c;
  const auto& tri = mesh.triangles[t];
  for (int a = 0; a < 3; ++a) c[a] = w.v1[tri[a]], c[3 + a] = w.v2[tri[a]];
  c[6] = w.bubble(0, t), c[7] = w.bubble(1, t);
  return c;
}

}  // namespace

MiniVelocityBasis mini_velocity_basis(const P1Triangle& T, const Eigen::Vector3d& l) {
  MiniVelocityBasis B;
  for (int i = 0; i < 8; ++i) B.value[i].setZero(), B.grad[i].setZero();
  const Eigen::Vector2d gb = bubble_gradient(T, l);
  for (int c = 0; c < 2; ++c) {
    for (int a = 0; a < 3; ++a) {
      B.value[3 * c + a][c] = l[a];
      B.grad[3 * c + a].row(c) = T.grad.row(a);
    }
    B.value[6 + c][c] = bubble_value(l);
    B.grad[6 + c].row(c) = gb.transpose();
  }
  return B;
}

namespace {

// The mini space's scalar basis at λ: s = (λ1, λ2, λ3, b) and the gradients g_k; the
// vector basis is s_k e_c (mini_velocity_basis's index 3c + k, or 6 + c for the
// bubble). Working on the scalar basis makes the Jacobian two 4×4 products per
// quadrature point instead of 8×8 vector ones (mini_velocity_basis): 4–5× less time
// for the assembly and the bubbles' recovery, which Newton repeats every step.
struct ScalarBasis {
  Eigen::Vector4d s;
  Eigen::Matrix<double, 4, 2> g;
};

ScalarBasis scalar_basis(const P1Triangle& T, const Eigen::Vector3d& l) {
  ScalarBasis B;
  B.s << l[0], l[1], l[2], bubble_value(l);
  B.g.topRows<3>() = T.grad;
  B.g.row(3) = bubble_gradient(T, l).transpose();
  return B;
}

// Index of the vector basis function s_k e_c in the 8 local velocity unknowns.
int vector_index(int k, int c) { return k < 3 ? 3 * c + k : 6 + c; }

}  // namespace

// J[(c,k),(d,l)] = ρ ∫ s_k [δ_cd (w·∇)s_l + s_l ∂_d w_c]: (w·∇)φ_j + (φ_j·∇)w tested with φ_i.
void NewtonConvection::add(int t, const P1Triangle& T, MiniLocal& e) const {
  const Eigen::Matrix<double, 8, 1> c = local_coefficients(mesh_, w_, t);
  static const TriangleRule rule = triangle_rule(8);  // computed once: 25 points
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();     // ∫ s_k (w·∇)s_l
  Eigen::Matrix4d S[2][2];                         // ∫ s_k s_l ∂_d w_c
  for (auto& row : S)
    for (auto& m : row) m.setZero();
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const ScalarBasis B = scalar_basis(T, rule.lambda[q]);
    const Eigen::Vector2d w(c.segment<3>(0).dot(B.s.head<3>()) + c[6] * B.s[3],
                            c.segment<3>(3).dot(B.s.head<3>()) + c[7] * B.s[3]);
    const double dx = rho_ * rule.w[q] * T.area;
    A.noalias() += (dx * B.s) * (B.g * w).transpose();
    if (picard_) continue;
    Eigen::Matrix2d grad_w;  // row c: ∇w_c
    grad_w.row(0) = c.segment<3>(0).transpose() * B.g.topRows<3>() + c[6] * B.g.row(3);
    grad_w.row(1) = c.segment<3>(3).transpose() * B.g.topRows<3>() + c[7] * B.g.row(3);
    const Eigen::Matrix4d ss = (dx * B.s) * B.s.transpose();
    for (int ci = 0; ci < 2; ++ci)
      for (int d = 0; d < 2; ++d) S[ci][d] += grad_w(ci, d) * ss;
  }
  Eigen::Matrix<double, 8, 8> J = Eigen::Matrix<double, 8, 8>::Zero();  // row: test φ_i; column: trial φ_j
  for (int ci = 0; ci < 2; ++ci)
    for (int d = 0; d < 2; ++d)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l)
          J(vector_index(k, ci), vector_index(l, d)) += (ci == d ? A(k, l) : 0.0) + (picard_ ? 0.0 : S[ci][d](k, l));
  e.M.topLeftCorner<6, 6>() += J.topLeftCorner<6, 6>();
  e.E_col.topRows<6>() += J.topRightCorner<6, 2>();
  e.E_row.leftCols<6>() += J.bottomLeftCorner<2, 6>();
  e.A_bb += J.bottomRightCorner<2, 2>();
  e.symmetric = false;
}

void NewtonConvection::add_load(int t, const P1Triangle& T, ElementLoad& load) const {
  if (picard_) return;  // Oseen's system has the Stokes load alone
  const Eigen::Matrix<double, 8, 1> c = local_coefficients(mesh_, w_, t);
  static const TriangleRule rule = triangle_rule(8);  // computed once: 25 points
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const ScalarBasis B = scalar_basis(T, rule.lambda[q]);
    const Eigen::Vector2d w(c.segment<3>(0).dot(B.s.head<3>()) + c[6] * B.s[3],
                            c.segment<3>(3).dot(B.s.head<3>()) + c[7] * B.s[3]);
    Eigen::Matrix2d grad_w;
    grad_w.row(0) = c.segment<3>(0).transpose() * B.g.topRows<3>() + c[6] * B.g.row(3);
    grad_w.row(1) = c.segment<3>(3).transpose() * B.g.topRows<3>() + c[7] * B.g.row(3);
    const Eigen::Vector2d N = rho_ * rule.w[q] * T.area * (grad_w * w);  // ρ (w·∇)w dx
    for (int cc = 0; cc < 2; ++cc) {
      for (int a = 0; a < 3; ++a) load.F_V[3 * cc + a] += B.s[a] * N[cc];
      load.F_b[cc] += B.s[3] * N[cc];
    }
  }
}

}  // namespace fsi
