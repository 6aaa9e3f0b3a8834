#include "mesh/mesh_validation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <tuple>

#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// |area| below this fraction of the longest edge squared counts as zero: far below
// any triangle Gmsh makes (those have angles of degrees), far above round-off.
constexpr double kDegenerate = 1e-12;
// Around a node the angles of a planar triangulation sum to 2π at most; a fold
// (the triangles turning twice around it) gives 4π. The tolerance is round-off.
constexpr double kFullTurn = 2 * std::numbers::pi * (1 + 1e-9);

std::string node(const MeshOrigin& o, int v) {
  return std::to_string(o.node_tags[v]);
}
std::string triangle(const MeshOrigin& o, int t) {
  return std::to_string(o.triangle_tags[t]);
}

double twice_area(const Mesh& m, const std::array<int, 3>& t) {
  const Point e1 = m.vertices[t[1]] - m.vertices[t[0]], e2 = m.vertices[t[2]] - m.vertices[t[0]];
  return e1.x() * e2.y() - e1.y() * e2.x();
}

void check_shapes(const Mesh& m, const MeshOrigin& o) {
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] == tri[(k + 1) % 3])
        throw MeshError("triangle " + triangle(o, t) + " uses node " + node(o, tri[k]) + " twice");
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest =
          std::max(longest, (m.vertices[tri[k]] - m.vertices[tri[(k + 1) % 3]]).squaredNorm());
    if (!(std::abs(twice_area(m, tri)) > 2 * kDegenerate * longest))
      throw MeshError("triangle " + triangle(o, t) + " has zero area (nodes " + node(o, tri[0]) +
                      ", " + node(o, tri[1]) + ", " + node(o, tri[2]) + " are collinear)");
  }
}

// One orientation per surface entity; a clockwise surface is turned as a whole.
void orient_surfaces(Mesh& m, const MeshOrigin& o) {
  std::map<int, std::array<int, 2>> first;  // surface → first clockwise, first counter-clockwise
  for (int t = 0; t < m.num_triangles(); ++t) {
    auto [it, added] = first.try_emplace(o.triangle_surfaces[t], std::array<int, 2>{-1, -1});
    int& slot = it->second[twice_area(m, m.triangles[t]) > 0];
    if (slot < 0) slot = t;
  }
  for (const auto& [surface, f] : first)
    if (f[0] >= 0 && f[1] >= 0)
      throw MeshError("surface " + std::to_string(surface) + " is tangled: triangle " +
                      triangle(o, f[0]) + " is clockwise, triangle " + triangle(o, f[1]) +
                      " counter-clockwise (an inverted or folded part)");
  for (int t = 0; t < m.num_triangles(); ++t)
    if (first.at(o.triangle_surfaces[t])[1] < 0) std::swap(m.triangles[t][1], m.triangles[t][2]);
}

// The triangles' edges, row a holding the uses of every edge (a, b) with a < b,
// sorted by b: short rows, sorted apiece (a global sort of the 1.25M edge uses of a
// 417k-triangle mesh was the slowest part of validating it).
class EdgeTable {
 public:
  struct Use {
    int b, triangle;
    bool forward;  // the triangle goes from a to b
    bool operator<(const Use& u) const { return std::tie(b, triangle) < std::tie(u.b, u.triangle); }
  };
  explicit EdgeTable(const Mesh& m)
      : start_(m.vertices.size() + 1, 0), uses_(3 * m.triangles.size()) {
    auto each_edge = [&](auto&& f) {
      for (int t = 0; t < m.num_triangles(); ++t)
        for (int k = 0; k < 3; ++k) f(t, m.triangles[t][k], m.triangles[t][(k + 1) % 3]);
    };
    each_edge([&](int, int u, int v) { ++start_[std::min(u, v) + 1]; });
    for (std::size_t a = 1; a < start_.size(); ++a) start_[a] += start_[a - 1];
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    each_edge([&](int t, int u, int v) {
      uses_[next[std::min(u, v)]++] = {std::max(u, v), t, u < v};
    });
    for (std::size_t a = 0; a + 1 < start_.size(); ++a)
      std::sort(uses_.begin() + static_cast<std::ptrdiff_t>(start_[a]),
                uses_.begin() + static_cast<std::ptrdiff_t>(start_[a + 1]));
  }
  int num_vertices() const { return static_cast<int>(start_.size()) - 1; }
  std::span<const Use> row(int a) const {
    return {uses_.data() + start_[a], uses_.data() + start_[a + 1]};
  }
  // The uses of edge (a, b), a < b.
  std::span<const Use> uses(int a, int b) const {
    const auto r = row(a);
    const auto lo = std::lower_bound(r.begin(), r.end(), Use{b, -1, false});
    auto hi = lo;
    while (hi != r.end() && hi->b == b) ++hi;
    return {lo, hi};
  }

 private:
  std::vector<std::size_t> start_;
  std::vector<Use> uses_;
};

void check_edges(const EdgeTable& edges, const MeshOrigin& o) {
  for (int a = 0; a < edges.num_vertices(); ++a) {
    const auto r = edges.row(a);
    for (auto i = r.begin(); i != r.end();) {
      auto j = i;
      while (j != r.end() && j->b == i->b) ++j;
      const std::string edge = "nodes " + node(o, a) + " and " + node(o, i->b);
      if (j - i > 2)
        throw MeshError("the edge between " + edge + " belongs to " + std::to_string(j - i) +
                        " triangles (" + triangle(o, i[0].triangle) + ", " +
                        triangle(o, i[1].triangle) + ", " + triangle(o, i[2].triangle) +
                        "); at most two may share an edge");
      if (j - i == 2 && i[0].forward == i[1].forward)
        throw MeshError("triangles " + triangle(o, i[0].triangle) + " and " +
                        triangle(o, i[1].triangle) +
                        " overlap: both lie on the same side of their common edge (" + edge + ")");
      i = j;
    }
  }
}

void check_turns(const Mesh& m, const MeshOrigin& o) {
  std::vector<double> angle_sum(m.vertices.size(), 0.0);
  for (const auto& tri : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Point& p = m.vertices[tri[k]];
      const Point e1 = m.vertices[tri[(k + 1) % 3]] - p, e2 = m.vertices[tri[(k + 2) % 3]] - p;
      angle_sum[tri[k]] += std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
    }
  for (int v = 0; v < m.num_vertices(); ++v)
    if (angle_sum[v] > kFullTurn)
      throw MeshError(
          "the triangles around node " + node(o, v) + " turn " +
          std::to_string(static_cast<int>(std::lround(angle_sum[v] * 180 / std::numbers::pi))) +
          " degrees around it (a planar mesh: 360 at most); the mesh is folded");
}

void check_boundary_edges(const Mesh& m, const EdgeTable& edges, const MeshOrigin& o) {
  std::vector<bool> in_triangle(m.vertices.size(), false);
  for (const auto& tri : m.triangles)
    for (int v : tri) in_triangle[v] = true;
  std::vector<std::tuple<int, int, std::size_t>> seen;  // (a, b, boundary edge index)
  for (std::size_t i = 0; i < m.boundary_edges.size(); ++i) {
    const auto& e = m.boundary_edges[i];
    const std::string line = "line " + std::to_string(o.edge_tags[i]) + " of '" +
                             m.label_names[e.label] + "' (nodes " + node(o, e.v[0]) + ", " +
                             node(o, e.v[1]) + ")";
    for (int v : e.v)
      if (!in_triangle[v])
        throw MeshError("node " + node(o, v) + " of " + line + " belongs to no triangle");
    const int a = std::min(e.v[0], e.v[1]), b = std::max(e.v[0], e.v[1]);
    const auto uses = a == b ? std::span<const EdgeTable::Use>{} : edges.uses(a, b);
    if (uses.empty()) throw MeshError(line + " is not an edge of any triangle");
    if (uses.size() > 1)
      throw MeshError(line + " lies inside the domain, between triangles " +
                      triangle(o, uses[0].triangle) + " and " + triangle(o, uses[1].triangle) +
                      "; a boundary line must be on its boundary");
    seen.emplace_back(a, b, i);
  }
  std::sort(seen.begin(), seen.end());
  for (std::size_t k = 1; k < seen.size(); ++k)
    if (std::get<0>(seen[k]) == std::get<0>(seen[k - 1]) &&
        std::get<1>(seen[k]) == std::get<1>(seen[k - 1])) {
      const auto i = std::get<2>(seen[k - 1]), j = std::get<2>(seen[k]);
      throw MeshError("the edge between nodes " + node(o, std::get<0>(seen[k])) + " and " +
                      node(o, std::get<1>(seen[k])) + " is a boundary line twice: line " +
                      std::to_string(o.edge_tags[i]) + " of '" +
                      m.label_names[m.boundary_edges[i].label] + "' and line " +
                      std::to_string(o.edge_tags[j]) + " of '" +
                      m.label_names[m.boundary_edges[j].label] + "'");
    }
}

}  // namespace

void orient_and_validate(Mesh& mesh, const MeshOrigin& origin) {
  if (mesh.triangles.empty()) throw MeshError("the mesh has no triangles");
  check_shapes(mesh, origin);
  orient_surfaces(mesh, origin);
  const EdgeTable edges(mesh);
  check_edges(edges, origin);
  check_boundary_edges(mesh, edges, origin);
  check_turns(mesh, origin);
}

}  // namespace fsi
