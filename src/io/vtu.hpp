// VTK XML unstructured-grid (.vtu) and collection (.pvd) files for ParaView.
// Written by hand (ASCII, full precision): the format is a few dozen lines of XML,
// and Debian's VTK (libvtk9-dev) would add ~100 MB of dependencies for it.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

struct VtuField {
  std::string name;
  int components = 1;          // 1 (scalar) or 3 (vector; 2D vectors padded with 0)
  std::vector<double> values;  // size = count × components
  bool on_cells = false;       // point data (per vertex) or cell data (per triangle)
};

// A 2D vector field given as two per-vertex (or per-cell) components.
VtuField vector_field(const std::string& name, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                      bool on_cells = false);
VtuField scalar_field(const std::string& name, const Eigen::VectorXd& v, bool on_cells = false);

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields);
// Quadratic triangles (VTK_QUADRATIC_TRIANGLE, type 22; structure.element = "P2"):
// `cells` six indices into `nodes` each, the vertices and then the midpoints of the
// edges 0→1, 1→2, 2→0, which is VTK's order and P2Space's. Point data on the nodes.
void write_quadratic_vtu(const std::string& path, const std::vector<Point>& nodes,
                         const std::vector<std::array<int, 6>>& cells, const std::vector<VtuField>& fields);

struct PvdEntry {
  std::string file;  // relative to the .pvd
  int part = 0;
};
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace fsi
