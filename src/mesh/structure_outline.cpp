#include "mesh/structure_outline.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// Vertex → its neighbours along the boundary edges not labelled `clamped_label`.
std::map<int, std::vector<int>> outline_neighbours(const Mesh& mesh, int clamped_label) {
  std::map<int, std::vector<int>> next;
  for (const auto& e : mesh.boundary_edges)
    if (e.label != clamped_label) {
      next[e.v[0]].push_back(e.v[1]);
      next[e.v[1]].push_back(e.v[0]);
    }
  return next;
}

// The two ends of the chain: vertices of Γ_D met by one outline edge.
std::vector<int> outline_ends(const Mesh& mesh, int clamped_label,
                              const std::map<int, std::vector<int>>& next) {
  std::vector<int> ends;
  for (int v : mesh.vertices_on(clamped_label)) {
    auto it = next.find(v);
    if (it != next.end() && it->second.size() == 1) ends.push_back(v);
  }
  if (ends.size() != 2)
    throw MeshError("the structure's boundary off " + mesh.label_names[clamped_label] + " has " +
                    std::to_string(ends.size()) +
                    " ends on it; the body-fitted fluid mesh needs one chain from one end of " +
                    mesh.label_names[clamped_label] + " to the other");
  const Point &a = mesh.vertices[ends[0]], &b = mesh.vertices[ends[1]];
  if (b.y() < a.y() || (b.y() == a.y() && b.x() < a.x())) std::swap(ends[0], ends[1]);
  return ends;
}

}  // namespace

std::vector<int> structure_outline(const Mesh& mesh, int clamped_label) {
  const std::map<int, std::vector<int>> next = outline_neighbours(mesh, clamped_label);
  const std::vector<int> ends = outline_ends(mesh, clamped_label, next);
  std::vector<int> chain = {ends[0]};
  std::set<int> seen = {ends[0]};
  for (int previous = -1, v = ends[0]; v != ends[1];) {
    const std::vector<int>& n = next.at(v);
    if (n.size() > 2)
      throw MeshError("the structure's boundary branches at a vertex: it is not one chain");
    const int w = n[0] != previous ? n[0] : n.size() > 1 ? n[1] : -1;
    if (w < 0 || !seen.insert(w).second)
      throw MeshError("the structure's boundary off the clamped side is not one simple chain");
    previous = v, v = w;
    chain.push_back(v);
  }
  std::size_t edges = 0;
  for (const auto& [v, n] : next) edges += n.size();
  if (edges / 2 != chain.size() - 1)
    throw MeshError(
        "the structure's boundary off the clamped side has a part besides the chain between its "
        "ends "
        "(a hole?); the body-fitted fluid mesh needs one chain");
  return chain;
}

std::vector<int> match_vertices(const Mesh& mesh, int label, const std::vector<Point>& points,
                                double tolerance) {
  const std::vector<int> candidates = mesh.vertices_on(label);
  std::vector<int> out;
  std::set<int> used;
  for (const Point& p : points) {
    int best = -1;
    double best_distance = tolerance;
    for (int v : candidates) {
      const double d = (mesh.vertices[v] - p).norm();
      if (d <= best_distance) best = v, best_distance = d;
    }
    if (best < 0 || !used.insert(best).second)
      throw MeshError("a point of the structure's outline (" + std::to_string(p.x()) + ", " +
                      std::to_string(p.y()) + ") is not one vertex of " + mesh.label_names[label] +
                      " of its own");
    out.push_back(best);
  }
  return out;
}

}  // namespace fsi
