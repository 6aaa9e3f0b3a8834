#include "solid/normal_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace fsi {
namespace {

Point displaced_vertex(const Mesh& mesh, const Eigen::VectorXd& u, int v) {
  const int nv = mesh.num_vertices();
  return mesh.vertices[v] + Point(u[v], u[nv + v]);
}

}  // namespace

CandidateSet candidate_vertices(const Mesh& mesh, const std::string& boundary, int gamma_c, int gamma_d) {
  std::vector<double> weight(static_cast<std::size_t>(mesh.num_vertices()), 0.0);
  std::vector<char> on_d(static_cast<std::size_t>(mesh.num_vertices()), 0);
  for (int v : mesh.vertices_on(gamma_d)) on_d[v] = 1;
  const bool all = boundary == "all";
  if (!all && boundary != "Gamma_C") throw std::invalid_argument("candidate_vertices: boundary '" + boundary + "'");
  std::vector<int> degree(static_cast<std::size_t>(mesh.num_vertices()), 0);
  for (const BoundaryEdge& e : mesh.boundary_edges) {
    if (all ? e.label == gamma_d : e.label != gamma_c) continue;
    const double half = (mesh.vertices[e.v[1]] - mesh.vertices[e.v[0]]).norm() / 2;
    for (int v : e.v) weight[v] += half, ++degree[v];
  }
  CandidateSet out;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (degree[v] == 0 || on_d[v]) continue;
    // Γ_C's ends (one Γ_C edge) carry no row, as eq. (15)'s; "all" keeps every vertex.
    if (!all && degree[v] < 2) continue;
    out.vertices.push_back(v);
    out.weights.push_back(weight[v]);
  }
  return out;
}

ContactConstraint assemble_normal_contact(const Mesh& mesh, const CandidateSet& candidates,
                                          const std::vector<const Obstacle*>& obstacles, const Eigen::VectorXd& u_k) {
  const int nv = mesh.num_vertices();
  const int m = static_cast<int>(candidates.vertices.size());
  ContactConstraint c;
  c.C_S.resize(m, 2 * nv);
  c.c_lb.resize(m);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(2 * m));
  for (int i = 0; i < m; ++i) {
    const int v = candidates.vertices[static_cast<std::size_t>(i)];
    const double w = candidates.weights[static_cast<std::size_t>(i)];
    const SignedDistance s = nearest(obstacles, displaced_vertex(mesh, u_k, v)).gap;
    t.emplace_back(i, v, w * s.n.x());
    t.emplace_back(i, nv + v, w * s.n.y());
    c.c_lb[i] = w * (s.n.x() * u_k[v] + s.n.y() * u_k[nv + v] - s.d);
    c.row_vertex.push_back(v);
  }
  c.C_S.setFromTriplets(t.begin(), t.end());
  return c;
}

double min_exact_gap(const Mesh& mesh, const CandidateSet& candidates, const std::vector<const Obstacle*>& obstacles,
                     const Eigen::VectorXd& u) {
  double g = INFINITY;
  for (int v : candidates.vertices) g = std::min(g, nearest(obstacles, displaced_vertex(mesh, u, v)).gap.d);
  return g;
}

}  // namespace fsi
