// coupling.force = "large" (SPEC §11): the fluid's force on the structure pulled back
// exactly to Ω_S0. On a P1 triangle F, J and F⁻¹ are constant and ṽ, p̃ linear, so
//   ∫_T J σ F⁻ᵀ : ∇_X(φ_a e_c) = J |T| (σ̄ F⁻ᵀ)_c · ∇λ_a,  σ̄ = −p̄ I + 2μ_F sym(∇_X ṽ F⁻¹)
// (p̄ the mean of p̃ over T: σ is linear, its mean the vertex mean), the penalty term is
// J times the triangle's mass matrix applied to ṽ, and the body force is integrated at
// the deformed quadrature points times J. This equals the small form's integrals
// taken on the deformed triangles φ(T) (tested: tests/coupling/large_force_test.cpp).
#include "coupling/force_transfer.hpp"
#include "fem/integration.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi {

Eigen::VectorXd FluidForce::large(const SampledFluid& s, const Eigen::VectorXd& u) const {
  const int nv = mesh_.num_vertices();
  Eigen::VectorXd load = body_force(u, /*jacobian=*/true);
  for_each_triangle(mesh_, [&](int t, const P1Triangle& T) {
    const auto& tri = mesh_.triangles[t];
    const Matrix2 F = deformation_gradient(T, tri, u, nv);
    const double J = F.determinant();
    const Matrix2 Finv = F.inverse();
    Matrix2 grad_v = Matrix2::Zero();  // ∇_X ṽ, row c = ∇ṽ_c
    double p_mean = 0;
    for (int a = 0; a < 3; ++a) {
      for (int c = 0; c < 2; ++c) grad_v.row(c) += s.v[dof(tri[a], c, nv)] * T.grad.row(a);
      p_mean += s.p[tri[a]] / 3;
    }
    const Matrix2 L = grad_v * Finv;  // ∇_x v
    const Matrix2 sigma = -p_mean * Matrix2::Identity() + mu_F_ * (L + L.transpose());
    const Matrix2 PK = J * T.area * sigma * Finv.transpose();
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) {
        double mass = 0;  // (1/ε) J ∫_T ṽ_c λ_a, ∫ λ_a λ_b = |T|(1 + δ_ab)/12
        for (int b = 0; b < 3; ++b) mass += s.v[dof(tri[b], c, nv)] * T.area * (a == b ? 2.0 : 1.0) / 12.0;
        load[dof(tri[a], c, nv)] += PK.row(c).dot(T.grad.row(a)) + J * mass / eps_;
      }
  });
  return load;
}

}  // namespace fsi
