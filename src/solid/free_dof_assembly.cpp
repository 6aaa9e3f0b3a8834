#include "solid/free_dof_assembly.hpp"

#include <algorithm>
#include <stdexcept>

#include "solid/elasticity.hpp"

namespace fsi {
namespace {

// Local index (vertex a, component c) of a triangle's 6 dofs.
int local(int a, int c) { return 3 * c + a; }

}  // namespace

FreeDofAssembler::FreeDofAssembler(const Mesh& mesh, const std::vector<int>& free_dofs, const SparseMatrix& pattern)
    : mesh_(mesh) {
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();
  reduced_.assign(2 * nv, -1);
  for (std::size_t k = 0; k < free_dofs.size(); ++k) reduced_[free_dofs[k]] = static_cast<int>(k);
  geometry_.reserve(nt);
  slot_.assign(36 * static_cast<std::size_t>(nt), -1);
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (int t = 0; t < nt; ++t) {
    geometry_.emplace_back(mesh, t);
    const auto& tri = mesh.triangles[t];
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        const int r = reduced_[dof(tri[i % 3], i / 3, nv)], col = reduced_[dof(tri[j % 3], j / 3, nv)];
        if (r < 0 || col < 0) continue;
        const int* pos = std::lower_bound(inner + outer[col], inner + outer[col + 1], r);
        if (pos == inner + outer[col + 1] || *pos != r)
          throw std::logic_error("FreeDofAssembler: the pattern lacks a coupling of the mesh");
        slot_[36 * static_cast<std::size_t>(t) + 6 * i + j] = static_cast<int>(pos - inner);
      }
  }
}

Matrix2 FreeDofAssembler::gradient(int t, const Eigen::VectorXd& u) const {
  return deformation_gradient(geometry_[t], mesh_.triangles[t], u, mesh_.num_vertices());
}

Eigen::VectorXd FreeDofAssembler::force(const Material& m, const Eigen::VectorXd& u) const {
  const int nv = mesh_.num_vertices();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(
      std::count_if(reduced_.begin(), reduced_.end(), [](int r) { return r >= 0; })));
  for (int t = 0; t < mesh_.num_triangles(); ++t) {
    const P1Triangle& T = geometry_[t];
    const Matrix2 P = m.stress(gradient(t, u));
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) {
        const int r = reduced_[dof(mesh_.triangles[t][a], c, nv)];
        if (r >= 0) f[r] += T.area * P.row(c).dot(T.grad.row(a));
      }
  }
  return f;
}

void FreeDofAssembler::tangent(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const {
  double* values = K.valuePtr();
  std::fill(values, values + K.nonZeros(), 0.0);
  for (int t = 0; t < mesh_.num_triangles(); ++t) {
    const P1Triangle& T = geometry_[t];
    const Matrix2 F = gradient(t, u);
    const int* slots = &slot_[36 * static_cast<std::size_t>(t)];
    const Eigen::Matrix4d A = m.moduli(F);
    // K_(a c),(b d) = |T| Σ_{J,L} A(2c + J, 2d + L) ∂_J λ_a ∂_L λ_b, A ∇λ_b once per (b, d).
    for (int b = 0; b < 3; ++b)
      for (int d = 0; d < 2; ++d) {
        const Eigen::Vector4d Ag = A.middleCols<2>(2 * d) * T.grad.row(b).transpose();
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 2; ++c) {
            const int s = slots[6 * local(a, c) + local(b, d)];
            if (s >= 0) values[s] += T.area * (Ag[2 * c] * T.grad(a, 0) + Ag[2 * c + 1] * T.grad(a, 1));
          }
      }
  }
}

}  // namespace fsi
