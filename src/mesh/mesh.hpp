// The one triangulation type used everywhere: vertices, counter-clockwise
// triangles, and boundary edges carrying a named label (Gamma_D, Sigma_4, ...).
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace fsi {

using Point = Eigen::Vector2d;

struct BoundaryEdge {
  std::array<int, 2> v;  // vertex indices
  int label;             // index into Mesh::label_names
};

struct Mesh {
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise
  std::vector<BoundaryEdge> boundary_edges;
  std::vector<std::string> label_names;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_triangles() const { return static_cast<int>(triangles.size()); }

  // Label index of a boundary part; throws std::out_of_range naming it if absent.
  int label(const std::string& name) const;
  bool has_label(const std::string& name) const;
  // Label index, adding the name if new (for mesh builders).
  int add_label(const std::string& name);

  double area(int t) const;
  // Sorted, unique vertex indices of the edges carrying `label`.
  std::vector<int> vertices_on(int label) const;
  // Edges carrying `label`.
  std::vector<BoundaryEdge> edges_on(int label) const;
};

struct MeshStatistics {
  int triangles = 0;
  int vertices = 0;
  double min_angle_deg = 0;  // smallest interior angle over all triangles
  double h_min = 0;          // shortest edge
  double h_max = 0;          // longest edge
};

MeshStatistics statistics(const Mesh& mesh);

// Deformed copy: vertex i moved by displacement (u1[i], u2[i]).
Mesh displaced(const Mesh& mesh, const Eigen::VectorXd& u1, const Eigen::VectorXd& u2);

// Per vertex, the sorted vertices that share a triangle with it, itself among them
// (the pattern of a P1 matrix's row).
std::vector<std::vector<int>> vertex_neighbours(const Mesh& mesh);

}  // namespace fsi
