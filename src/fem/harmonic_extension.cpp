#include "fem/harmonic_extension.hpp"

#include <stdexcept>

#include "fem/p1.hpp"

namespace fsi {

HarmonicExtension::HarmonicExtension(const Mesh& mesh)
    : mesh_(mesh), interior_index_(mesh.num_vertices(), 0) {
  for (const auto& e : mesh_.boundary_edges) interior_index_[e.v[0]] = interior_index_[e.v[1]] = -1;
  int n = 0;
  for (int& i : interior_index_)
    if (i == 0) i = n++;
  std::vector<Eigen::Triplet<double>> II, IB;
  for (int t = 0; t < mesh_.num_triangles(); ++t) {
    const P1Triangle T(mesh_, t);
    // ∫ k ∇λ_a·∇λ_b with k = 1/|T|: the element matrix G Gᵀ (|T| k = 1).
    const Eigen::Matrix3d K = T.grad * T.grad.transpose();
    for (int a = 0; a < 3; ++a) {
      const int i = interior_index_[mesh_.triangles[t][a]];
      if (i < 0) continue;
      for (int b = 0; b < 3; ++b) {
        const int vb = mesh_.triangles[t][b], j = interior_index_[vb];
        if (j >= 0)
          II.emplace_back(i, j, K(a, b));
        else
          IB.emplace_back(i, vb, K(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(II.begin(), II.end());
  A_IB_.resize(n, mesh_.num_vertices());
  A_IB_.setFromTriplets(IB.begin(), IB.end());
  A_II_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(A);
  if (A_II_->info() != Eigen::Success)
    throw std::runtime_error("the mesh motion's Laplacian is singular");
}

Mesh HarmonicExtension::moved(const std::vector<Point>& boundary_d) const {
  if (boundary_d.size() != mesh_.vertices.size())
    throw std::invalid_argument("one displacement per vertex");
  Mesh out = mesh_;
  for (int c = 0; c < 2; ++c) {
    Eigen::VectorXd dB = Eigen::VectorXd::Zero(mesh_.num_vertices());
    for (int v = 0; v < mesh_.num_vertices(); ++v)
      if (interior_index_[v] < 0) dB[v] = boundary_d[v][c];
    const Eigen::VectorXd dI = A_II_->solve(-(A_IB_ * dB));
    for (int v = 0; v < mesh_.num_vertices(); ++v)
      out.vertices[v][c] += interior_index_[v] < 0 ? dB[v] : dI[interior_index_[v]];
  }
  return out;
}

double min_angle_deg(const Mesh& mesh) {
  for (int t = 0; t < mesh.num_triangles(); ++t)
    if (!(mesh.area(t) > 0)) return -1;  // inverted or flat (Mesh::area is signed)
  return statistics(mesh).min_angle_deg;
}

}  // namespace fsi
