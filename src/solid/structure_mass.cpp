#include "solid/structure_mass.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

SparseMatrix consistent_mass(const Mesh& mesh, const P2Space* p2, double rho) {
  if (!p2) return rho * assemble_vector_mass(mesh);
  const int n = p2->num_nodes();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(p2->mesh().num_triangles()) * 72);
  Eigen::Matrix<double, 6, 6> m;
  // N_a N_b is of degree 4: the degree-4 rule is exact. Element by element so the
  // triplets are 36 per component and triangle, not per quadrature point.
  const TriangleRule rule = triangle_rule(4);
  for (int e = 0; e < p2->mesh().num_triangles(); ++e) {
    const P1Triangle T(p2->mesh(), e);
    m.setZero();
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const P2Values v = p2_values(T, rule.lambda[q]);
      const Eigen::Map<const Eigen::Matrix<double, 6, 1>> N(v.N.data());
      m += (rho * rule.w[q] * T.area) * N * N.transpose();
    }
    const auto& nodes = p2->element(e);
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        for (int c = 0; c < 2; ++c) t.emplace_back(dof(nodes[a], c, n), dof(nodes[b], c, n), m(a, b));
  }
  SparseMatrix M(2 * n, 2 * n);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

namespace {

// The not-massless vertex nearest to v.
int nearest_massive(const Mesh& mesh, int v, const std::vector<char>& massless) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int w = 0; w < mesh.num_vertices(); ++w)
    if (!massless[w] && (mesh.vertices[w] - mesh.vertices[v]).squaredNorm() < best_d)
      best = w, best_d = (mesh.vertices[w] - mesh.vertices[v]).squaredNorm();
  return best;
}

}  // namespace

SparseMatrix redistributed_mass(const Mesh& mesh, const std::vector<int>& massless_vertices, double rho) {
  const int nv = mesh.num_vertices();
  std::vector<double> m(static_cast<std::size_t>(nv), 0.0);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const double share = rho * P1Triangle(mesh, t).area / 3;
    for (int v : mesh.triangles[t]) m[v] += share;
  }
  std::vector<char> massless(static_cast<std::size_t>(nv), 0);
  for (int v : massless_vertices) massless.at(v) = 1;
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(nv));
  for (const auto& tri : mesh.triangles)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (massless[tri[a]] && !massless[tri[b]]) neighbours[tri[a]].push_back(tri[b]);
  std::vector<double> moved = m;
  for (int v = 0; v < nv; ++v) {
    if (!massless[v]) continue;
    auto& to = neighbours[v];
    std::sort(to.begin(), to.end());
    to.erase(std::unique(to.begin(), to.end()), to.end());
    if (to.empty()) {
      const int w = nearest_massive(mesh, v, massless);
      if (w < 0) throw std::invalid_argument("redistributed_mass: every vertex is a contact node");
      to.push_back(w);
    }
    for (int w : to) moved[w] += m[v] / static_cast<double>(to.size());
    moved[v] = 0;
  }
  SparseMatrix M(2 * nv, 2 * nv);
  M.reserve(Eigen::VectorXi::Constant(2 * nv, 1));
  for (int c = 0; c < 2; ++c)
    for (int v = 0; v < nv; ++v) M.insert(dof(v, c, nv), dof(v, c, nv)) = moved[v];
  M.makeCompressed();
  return M;
}

}  // namespace fsi
