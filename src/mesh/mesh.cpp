#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fsi {

int Mesh::label(const std::string& name) const {
  for (std::size_t i = 0; i < label_names.size(); ++i)
    if (label_names[i] == name) return static_cast<int>(i);
  throw std::out_of_range("mesh has no boundary part named '" + name + "'");
}

bool Mesh::has_label(const std::string& name) const {
  return std::find(label_names.begin(), label_names.end(), name) != label_names.end();
}

int Mesh::add_label(const std::string& name) {
  if (has_label(name)) return label(name);
  label_names.push_back(name);
  return static_cast<int>(label_names.size()) - 1;
}

double Mesh::area(int t) const {
  const auto& [a, b, c] = triangles[t];
  const Point e1 = vertices[b] - vertices[a], e2 = vertices[c] - vertices[a];
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

std::vector<int> Mesh::vertices_on(int lab) const {
  std::vector<int> out;
  for (const auto& e : boundary_edges)
    if (e.label == lab) out.insert(out.end(), e.v.begin(), e.v.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<BoundaryEdge> Mesh::edges_on(int lab) const {
  std::vector<BoundaryEdge> out;
  for (const auto& e : boundary_edges)
    if (e.label == lab) out.push_back(e);
  return out;
}

MeshStatistics statistics(const Mesh& mesh) {
  MeshStatistics s;
  s.triangles = mesh.num_triangles();
  s.vertices = mesh.num_vertices();
  s.min_angle_deg = 180.0;
  s.h_min = mesh.triangles.empty() ? 0.0 : INFINITY;
  for (const auto& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Point& p = mesh.vertices[tri[k]];
      const Point e1 = mesh.vertices[tri[(k + 1) % 3]] - p;
      const Point e2 = mesh.vertices[tri[(k + 2) % 3]] - p;
      const double angle = std::acos(std::clamp(e1.dot(e2) / (e1.norm() * e2.norm()), -1.0, 1.0));
      s.min_angle_deg = std::min(s.min_angle_deg, angle * 180.0 / std::numbers::pi);
      s.h_min = std::min(s.h_min, e1.norm());
      s.h_max = std::max(s.h_max, e1.norm());
    }
  }
  return s;
}

Mesh displaced(const Mesh& mesh, const Eigen::VectorXd& u1, const Eigen::VectorXd& u2) {
  Mesh out = mesh;
  for (int i = 0; i < mesh.num_vertices(); ++i) out.vertices[i] += Point(u1[i], u2[i]);
  return out;
}

std::vector<std::vector<int>> vertex_neighbours(const Mesh& mesh) {
  std::vector<std::vector<int>> adjacent(mesh.num_vertices());
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      for (int b : tri) adjacent[a].push_back(b);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacent;
}

}  // namespace fsi
