#include "fem/p2.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/vector_p1.hpp"

namespace fsi {

P2Space::P2Space(const Mesh& mesh) : mesh_(mesh), nodes_(mesh.vertices), edge_of_vertex_(mesh.num_vertices()) {
  elements_.reserve(mesh.num_triangles());
  auto midpoint = [&](int a, int b) {  // the edge {a, b}'s node, made on first sight
    const int lo = std::min(a, b), hi = std::max(a, b);
    for (const auto& [w, node] : edge_of_vertex_[lo])
      if (w == hi) return node;
    const int node = static_cast<int>(nodes_.size());
    nodes_.push_back(0.5 * (mesh.vertices[lo] + mesh.vertices[hi]));
    edge_of_vertex_[lo].push_back({hi, node});
    return node;
  };
  for (const auto& tri : mesh.triangles)
    elements_.push_back({tri[0], tri[1], tri[2], midpoint(tri[0], tri[1]), midpoint(tri[1], tri[2]),
                         midpoint(tri[2], tri[0])});
}

int P2Space::midpoint_of(const BoundaryEdge& e) const {
  const int lo = std::min(e.v[0], e.v[1]), hi = std::max(e.v[0], e.v[1]);
  for (const auto& [w, node] : edge_of_vertex_[lo])
    if (w == hi) return node;
  throw std::invalid_argument("P2Space: a boundary edge that is no triangle's edge");
}

std::vector<int> P2Space::nodes_on(int label) const {
  std::vector<int> out = mesh_.vertices_on(label);
  for (const BoundaryEdge& e : mesh_.edges_on(label)) out.push_back(midpoint_of(e));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Mesh nodal_mesh(const P2Space& space) {
  const Mesh& mesh = space.mesh();
  Mesh out;
  out.vertices = space.nodes();
  out.label_names = mesh.label_names;
  out.triangles.reserve(4 * mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const std::array<int, 6>& e = space.element(t);  // vertices 0 1 2, midpoints 01 12 20
    out.triangles.push_back({e[0], e[3], e[5]});       // counter-clockwise as the parent
    out.triangles.push_back({e[3], e[1], e[4]});
    out.triangles.push_back({e[5], e[4], e[2]});
    out.triangles.push_back({e[3], e[4], e[5]});
  }
  out.boundary_edges.reserve(2 * mesh.boundary_edges.size());
  for (const BoundaryEdge& b : mesh.boundary_edges) {
    const int m = space.midpoint_of(b);
    out.boundary_edges.push_back({{b.v[0], m}, b.label});
    out.boundary_edges.push_back({{m, b.v[1]}, b.label});
  }
  return out;
}

P2Values p2_values(const P1Triangle& T, const Eigen::Vector3d& l) {
  P2Values v;
  for (int a = 0; a < 3; ++a) {
    v.N[a] = l[a] * (2 * l[a] - 1);
    v.grad.row(a) = (4 * l[a] - 1) * T.grad.row(a);
  }
  for (int k = 0; k < 3; ++k) {
    const int m = (k + 1) % 3;
    v.N[3 + k] = 4 * l[k] * l[m];
    v.grad.row(3 + k) = 4 * (l[m] * T.grad.row(k) + l[k] * T.grad.row(m));
  }
  return v;
}

P2VectorAt p2_vector_at(const std::array<int, 6>& nodes, const P2Values& v, const Eigen::VectorXd& w, int n) {
  P2VectorAt out;
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 2; ++c) {
      out.value[c] += w[dof(nodes[i], c, n)] * v.N[i];
      out.grad.row(c) += w[dof(nodes[i], c, n)] * v.grad.row(i);
    }
  return out;
}

}  // namespace fsi
