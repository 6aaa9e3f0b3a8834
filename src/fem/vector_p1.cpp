#include "fem/vector_p1.hpp"

#include <algorithm>
#include <vector>

#include "fem/integration.hpp"

namespace fsi {

std::vector<int> both_components(const std::vector<int>& nodes, int n) {
  std::vector<int> dofs;
  for (int node : nodes)
    for (int c = 0; c < 2; ++c) dofs.push_back(dof(node, c, n));
  std::sort(dofs.begin(), dofs.end());
  return dofs;
}

SparseMatrix assemble_vector_mass(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  return assemble_on_triangles(mesh, 2 * nv, 2 * nv, 18, [&](int t, const P1Triangle& T, const auto& add) {
    const auto& tri = mesh.triangles[t];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)  // ∫ λ_a λ_b = |T|(1 + δ_ab)/12
        for (int c = 0; c < 2; ++c) add(dof(tri[a], c, nv), dof(tri[b], c, nv), T.area * (a == b ? 2.0 : 1.0) / 12.0);
  });
}

Eigen::VectorXd assemble_volume_load(const Mesh& mesh, const VectorField& f, int degree) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * nv);
  integrate_on_triangles(mesh, triangle_rule(degree), [&](int t, const P1Triangle&, const TrianglePoint& q) {
    const auto& tri = mesh.triangles[t];
    const Point fq = f(q.x) * q.dx;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) b[dof(tri[a], c, nv)] += fq[c] * q.lambda[a];
  });
  return b;
}

Eigen::VectorXd assemble_surface_load(const Mesh& mesh, int label, const VectorField& h,
                                      int points) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * nv);
  integrate_on_edges(mesh, mesh.edges_on(label), gauss_legendre(points), [&](const BoundaryEdge& e, const EdgePoint& q) {
    const Point hq = h(q.x) * q.ds;
    for (int c = 0; c < 2; ++c) {
      b[dof(e.v[0], c, nv)] += hq[c] * q.phi[0];
      b[dof(e.v[1], c, nv)] += hq[c] * q.phi[1];
    }
  });
  return b;
}

Eigen::VectorXd component(const Eigen::VectorXd& u, int c) {
  const Eigen::Index nv = u.size() / 2;
  return u.segment(c * nv, nv);
}

}  // namespace fsi
