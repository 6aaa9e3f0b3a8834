#include "solid/free_dof_assembly.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/quadrature.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

FreeDofAssembler::FreeDofAssembler(const Mesh& mesh, const std::vector<int>& free_dofs, const SparseMatrix& pattern)
    : n_(mesh.num_vertices()) {
  elements_.reserve(mesh.triangles.size());
  points_.reserve(mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    elements_.push_back({tri[0], tri[1], tri[2], -1, -1, -1});
    const P1Triangle T(mesh, t);
    QuadraturePoint q{Eigen::Matrix<double, 6, 2>::Zero(), T.area};
    q.grad.topRows<3>() = T.grad;
    points_.push_back(q);
  }
  index_slots(free_dofs, pattern);
}

// Degree 4, as solid/p2_elasticity.cpp's f_int and K_T: Saint-Venant–Kirchhoff's P(F)
// is cubic in ∇u, which is linear on a P2 triangle.
FreeDofAssembler::FreeDofAssembler(const P2Space& space, const std::vector<int>& free_dofs, const SparseMatrix& pattern)
    : nodes_(6), n_(space.num_nodes()) {
  const Mesh& mesh = space.mesh();
  const TriangleRule rule = triangle_rule(4);
  per_element_ = static_cast<int>(rule.w.size());
  elements_.reserve(mesh.triangles.size());
  points_.reserve(mesh.triangles.size() * rule.w.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    elements_.push_back(space.element(t));
    const P1Triangle T(mesh, t);
    for (std::size_t k = 0; k < rule.w.size(); ++k)
      points_.push_back({p2_values(T, rule.lambda[k]).grad, rule.w[k] * T.area});
  }
  index_slots(free_dofs, pattern);
}

void FreeDofAssembler::index_slots(const std::vector<int>& free_dofs, const SparseMatrix& pattern) {
  reduced_.assign(2 * static_cast<std::size_t>(n_), -1);
  for (std::size_t k = 0; k < free_dofs.size(); ++k) reduced_[free_dofs[k]] = static_cast<int>(k);
  const int local = 2 * nodes_;
  slot_.assign(static_cast<std::size_t>(local * local) * elements_.size(), -1);
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (int i = 0; i < local; ++i)
      for (int j = 0; j < local; ++j) {
        const int r = reduced_[dof(elements_[e][i % nodes_], i / nodes_, n_)];
        const int col = reduced_[dof(elements_[e][j % nodes_], j / nodes_, n_)];
        if (r < 0 || col < 0) continue;
        const int* pos = std::lower_bound(inner + outer[col], inner + outer[col + 1], r);
        if (pos == inner + outer[col + 1] || *pos != r)
          throw std::logic_error("FreeDofAssembler: the pattern lacks a coupling of the mesh");
        slot_[e * static_cast<std::size_t>(local * local) + static_cast<std::size_t>(local * i + j)] =
            static_cast<int>(pos - inner);
      }
}

// The loops below with the element's node count N as a constant (3: P1, 6: P2), so that
// they unroll: with N a run-time bound the §7.2 beam's P1 Newton step was ~20 % slower.
template <int N>
Matrix2 FreeDofAssembler::gradient(int e, const QuadraturePoint& q, const Eigen::VectorXd& u) const {
  Matrix2 F = Matrix2::Identity();
  for (int a = 0; a < N; ++a)
    for (int c = 0; c < 2; ++c) F.row(c) += u[dof(elements_[e][a], c, n_)] * q.grad.row(a);
  return F;
}

Eigen::VectorXd FreeDofAssembler::force(const Material& m, const Eigen::VectorXd& u) const {
  return nodes_ == 3 ? force_of<3>(m, u) : force_of<6>(m, u);
}

void FreeDofAssembler::tangent(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const {
  nodes_ == 3 ? tangent_of<3>(m, u, K) : tangent_of<6>(m, u, K);
}

template <int N>
Eigen::VectorXd FreeDofAssembler::force_of(const Material& m, const Eigen::VectorXd& u) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(
      std::count_if(reduced_.begin(), reduced_.end(), [](int r) { return r >= 0; })));
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e)
    for (int k = 0; k < per_element_; ++k) {
      const QuadraturePoint& q = points_of(e)[k];
      const Matrix2 P = m.stress(gradient<N>(e, q, u));
      for (int a = 0; a < N; ++a)
        for (int c = 0; c < 2; ++c) {
          const int r = reduced_[dof(elements_[e][a], c, n_)];
          if (r >= 0) f[r] += q.dx * P.row(c).dot(q.grad.row(a));
        }
    }
  return f;
}

template <int N>
void FreeDofAssembler::tangent_of(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const {
  double* values = K.valuePtr();
  std::fill(values, values + K.nonZeros(), 0.0);
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e)
    for (int k = 0; k < per_element_; ++k) {
      const QuadraturePoint& q = points_of(e)[k];
      const Eigen::Matrix4d A = m.moduli(gradient<N>(e, q, u));
      const int* slots = &slot_[static_cast<std::size_t>(e) * 4 * N * N];
      // K_(a c),(b d) = dx Σ_{J,L} A(2c + J, 2d + L) ∂_J N_a ∂_L N_b, A ∇N_b once per (b, d).
      for (int b = 0; b < N; ++b)
        for (int d = 0; d < 2; ++d) {
          const Eigen::Vector4d Ag = A.middleCols<2>(2 * d) * q.grad.row(b).transpose();
          for (int a = 0; a < N; ++a)
            for (int c = 0; c < 2; ++c) {
              const int s = slots[2 * N * (a + N * c) + b + N * d];
              if (s >= 0) values[s] += q.dx * (Ag[2 * c] * q.grad(a, 0) + Ag[2 * c + 1] * q.grad(a, 1));
            }
        }
    }
}

}  // namespace fsi
