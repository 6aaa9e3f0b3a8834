// Small Gmsh meshes written by hand (MSH 2.2 ASCII) for the tests of mesh checks.
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi::testing {

struct HandMesh {
  std::vector<std::array<double, 2>> nodes;                 // tags 1, 2, ...
  std::vector<std::array<int, 3>> triangles;                // node tags
  std::string domain = "Omega_S";                           // the triangles' physical surface
  std::vector<std::pair<std::string, std::vector<std::array<int, 2>>>> lines;  // physical curves
};

inline std::string msh22(const HandMesh& m) {
  std::ostringstream out;
  out.precision(17);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << m.lines.size() + 1 << "\n";
  for (std::size_t g = 0; g < m.lines.size(); ++g) out << "1 " << g + 1 << " \"" << m.lines[g].first << "\"\n";
  out << "2 " << m.lines.size() + 1 << " \"" << m.domain << "\"\n$EndPhysicalNames\n$Nodes\n" << m.nodes.size() << "\n";
  for (std::size_t i = 0; i < m.nodes.size(); ++i) out << i + 1 << " " << m.nodes[i][0] << " " << m.nodes[i][1] << " 0\n";
  std::size_t count = m.triangles.size();
  for (const auto& [name, edges] : m.lines) count += edges.size();
  out << "$EndNodes\n$Elements\n" << count << "\n";
  int id = 1;
  for (std::size_t g = 0; g < m.lines.size(); ++g)
    for (const auto& e : m.lines[g].second) out << id++ << " 1 2 " << g + 1 << " " << g + 1 << " " << e[0] << " " << e[1] << "\n";
  for (const auto& t : m.triangles)
    out << id++ << " 2 2 " << m.lines.size() + 1 << " " << m.lines.size() + 1 << " " << t[0] << " " << t[1] << " " << t[2] << "\n";
  out << "$EndElements\n";
  return out.str();
}

// A Mesh as a HandMesh: its triangles as the surface `domain`, its boundary edges as
// curves named by their labels (renamed by `rename`: from → to).
inline HandMesh hand_mesh(const Mesh& m, const std::string& domain,
                          const std::vector<std::pair<std::string, std::string>>& rename = {}) {
  HandMesh h;
  h.domain = domain;
  for (const Point& p : m.vertices) h.nodes.push_back({p.x(), p.y()});
  for (const auto& t : m.triangles) h.triangles.push_back({t[0] + 1, t[1] + 1, t[2] + 1});
  for (std::size_t l = 0; l < m.label_names.size(); ++l) {
    std::string name = m.label_names[l];
    for (const auto& [from, to] : rename)
      if (m.label_names[l] == from) name = to;
    std::vector<std::array<int, 2>> edges;
    for (const BoundaryEdge& e : m.boundary_edges)
      if (e.label == static_cast<int>(l)) edges.push_back({e.v[0] + 1, e.v[1] + 1});
    if (!edges.empty()) h.lines.emplace_back(name, std::move(edges));
  }
  return h;
}

}  // namespace fsi::testing
