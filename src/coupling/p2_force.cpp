// The fluid force on a P2 structure (structure.element = "P2", issue 14): eq. (33) and
// its pull-back (force_transfer.hpp) with ṽ, p̃ and u the P2 interpolants of their
// nodal values and w running over the six quadratic basis functions per triangle.
//   small: K_mu ṽ − B p̃ + (1/ε) M ṽ − ∫ (f_F∘φ)·w, the three matrices of the reference
//          P2 space built once, exact (rules of degree 2, 3, 4 for polynomial integrands
//          of those degrees); the body force by a degree-4 rule at φ(X) = X + u(X).
//   large: ∫ J σ F⁻ᵀ : ∇_X w + (1/ε) ∫ J ṽ·w − ∫ J (f_F∘φ)·w, F = I + ∇_X u varying in
//          the triangle, by a degree-6 rule (kLargeDegree below: why that degree).
#include "coupling/force_transfer.hpp"
#include "fem/p2.hpp"
#include "solid/p2_elasticity.hpp"

namespace fsi {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// The pull-back's integrand, J σ F⁻ᵀ = −p̃ cof F + μ_F (L + Lᵀ) cof F with
// L = ∇_X ṽ adj(F) / J, is rational in X when F varies (u quadratic), so no rule is
// exact. Degree 6 integrates exactly every polynomial part of it: the pressure term
// (p̃ cof F : ∇w, degree 2 + 1 + 1), the penalty term (J ṽ·w, degree 2 + 2 + 2) and the
// body force for an affine f_F (J (f_F∘φ)·w, degree 2 + 2 + 2; the runs' f_F is
// constant), and the whole form when u is affine (J constant). What remains, the
// viscous term's quadrature error for a varying F, falls as h⁷ (a smooth integrand),
// far below P2's own O(h³) interpolation error; degree 4 would leave the penalty
// term, the largest (1/ε), inexact.
constexpr int kLargeDegree = 6;

// B (2n × n): B_{(i,c),k} = ∫ ∂_c N_i N_k, the P2 pressure's divergence pairing of eq.
// (33); ∇N linear times N quadratic: exact at degree 3.
SparseMatrix p2_divergence(const P2Space& space) {
  const int n = space.num_nodes();
  Triplets entries;
  entries.reserve(72 * space.mesh().triangles.size());
  integrate_p2(
      space, triangle_rule(3),
      [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
        for (int a = 0; a < 6; ++a)
          for (int c = 0; c < 2; ++c)
            for (int k = 0; k < 6; ++k)
              entries.emplace_back(dof(nodes[a], c, n), nodes[k], dx * v.grad(a, c) * v.N[k]);
      });
  SparseMatrix B(2 * n, n);
  B.setFromTriplets(entries.begin(), entries.end());
  return B;
}

// The vector mass ∫ N_j N_i δ_cd of eq. (33)'s penalty term: exact at degree 4.
SparseMatrix p2_vector_mass(const P2Space& space) {
  const int n = space.num_nodes();
  Triplets entries;
  entries.reserve(72 * space.mesh().triangles.size());
  integrate_p2(
      space, triangle_rule(4),
      [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
        for (int a = 0; a < 6; ++a)
          for (int b = 0; b < 6; ++b)
            for (int c = 0; c < 2; ++c)
              entries.emplace_back(dof(nodes[a], c, n), dof(nodes[b], c, n), dx * v.N[a] * v.N[b]);
      });
  SparseMatrix M(2 * n, 2 * n);
  M.setFromTriplets(entries.begin(), entries.end());
  return M;
}

double scalar_at(const std::array<int, 6>& nodes, const P2Values& v, const Eigen::VectorXd& q) {
  double out = 0;
  for (int i = 0; i < 6; ++i) out += q[nodes[i]] * v.N[i];
  return out;
}

}  // namespace

FluidForce::FluidForce(const P2Space& space, double mu_F, double eps, const VectorField& f_F,
                       ForceModel model)
    : mesh_(space.mesh()),
      nodes_(std::make_shared<const Mesh>(nodal_mesh(space))),
      space_(&space),
      mu_F_(mu_F),
      eps_(eps),
      model_(model),
      f_F_(f_F),
      K_mu_(assemble_elasticity(space, Lame{0.0, mu_F})),  // λ = 0, μ = μ_F: 2μ_F ε:ε
      B_(p2_divergence(space)),
      M_(p2_vector_mass(space)) {}

// −∫ (f_F∘φ)·w of eq. (33), φ(X) = X + u(X) at the points of a degree-4 rule: exact
// for f_F affine (degree 2 after φ, times N's 2).
Eigen::VectorXd FluidForce::p2_body_force(const Eigen::VectorXd& u) const {
  const int n = space_->num_nodes();
  Eigen::VectorXd body = Eigen::VectorXd::Zero(2 * n);
  integrate_p2(
      *space_, triangle_rule(4),
      [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point& X, double dx) {
        const Point f = f_F_(X + p2_vector_at(nodes, v, u, n).value) * dx;
        for (int a = 0; a < 6; ++a)
          for (int c = 0; c < 2; ++c) body[dof(nodes[a], c, n)] -= f[c] * v.N[a];
      });
  return body;
}

// The pull-back (force_transfer.hpp, SPEC §11) point by point: at each X, F, J, σ from
// the P2 fields, then J σ F⁻ᵀ : ∇N_a + J ((1/ε) ṽ − f_F∘φ)·N_a.
Eigen::VectorXd FluidForce::p2_large(const SampledFluid& s, const Eigen::VectorXd& u) const {
  const int n = space_->num_nodes();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(2 * n);
  integrate_p2(
      *space_, triangle_rule(kLargeDegree),
      [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point& X, double dx) {
        const P2VectorAt disp = p2_vector_at(nodes, v, u, n);
        const P2VectorAt vel = p2_vector_at(nodes, v, s.v, n);
        const Matrix2 F = Matrix2::Identity() + disp.grad;
        const double J = F.determinant();
        const Matrix2 Finv = F.inverse();
        const Matrix2 L = vel.grad * Finv;  // ∇_x v
        const Matrix2 sigma =
            -scalar_at(nodes, v, s.p) * Matrix2::Identity() + mu_F_ * (L + L.transpose());
        const Matrix2 PK = (J * dx) * sigma * Finv.transpose();
        const Point mass = (J * dx) * (vel.value / eps_ - f_F_(X + disp.value));
        for (int a = 0; a < 6; ++a)
          for (int c = 0; c < 2; ++c)
            load[dof(nodes[a], c, n)] += PK.row(c).dot(v.grad.row(a)) + mass[c] * v.N[a];
      });
  return load;
}

}  // namespace fsi
