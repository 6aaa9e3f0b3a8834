// VTK XML unstructured-grid (.vtu) and collection (.pvd) files for ParaView.
// Written by hand: the format is a few dozen lines of XML, and Debian's VTK
// (libvtk9-dev) would add ~100 MB of dependencies for it. The arrays go in ParaView's
// appended raw encoding (binary, exact), optionally zlib-compressed, or as ASCII text
// (full precision): ASCII took most of a coarse run's output time (docs/performance.md).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// output.vtu_format: "binary" (appended raw) | "zlib" (appended, compressed) | "ascii".
enum class VtuFormat { binary, zlib, ascii };
// Throws std::invalid_argument naming the allowed values.
VtuFormat vtu_format(const std::string& name);

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

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields,
               VtuFormat format = VtuFormat::binary);
// Quadratic triangles (VTK_QUADRATIC_TRIANGLE, type 22; structure.element = "P2"):
// `cells` six indices into `nodes` each, the vertices and then the midpoints of the
// edges 0→1, 1→2, 2→0, which is VTK's order and P2Space's. Point data on the nodes.
void write_quadratic_vtu(const std::string& path, const std::vector<Point>& nodes,
                         const std::vector<std::array<int, 6>>& cells,
                         const std::vector<VtuField>& fields, VtuFormat format = VtuFormat::binary);

struct PvdEntry {
  std::string file;  // relative to the .pvd
  int part = 0;
  double time = 0;   // its timestep (a time series' frame; 0 for one state)
};
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace fsi
