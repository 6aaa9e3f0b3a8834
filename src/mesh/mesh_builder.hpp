// Gmsh's raw data (raw_mesh.hpp) → a Mesh: picks the triangles of the domain's
// physical surface and the lines of the named physical curves, and refuses what is
// not a usable first-order planar mesh. The geometric and topological checks that
// follow are in mesh_validation.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/raw_mesh.hpp"

namespace fsi {

// Gmsh's tags of what a Mesh was built from, to name a defect the way the file does.
struct MeshOrigin {
  std::vector<std::size_t> node_tags;      // per vertex
  std::vector<std::size_t> triangle_tags;  // per triangle
  std::vector<int> triangle_surfaces;      // per triangle: its surface entity
  std::vector<std::size_t> edge_tags;      // per boundary edge
};

struct BuiltMesh {
  Mesh mesh;
  MeshOrigin origin;
};

// Throws MeshError naming the first defect: Gmsh's notes of what it skipped, a
// missing or empty group, an element other than a 3-node triangle (surface) or a
// 2-node line (curves), an unknown or duplicated node, a non-finite or 3D coordinate.
// Labels follow `boundary_groups`' order.
BuiltMesh build_mesh(const RawMesh& raw, const std::vector<std::string>& boundary_groups,
                     const std::string& domain_group);

}  // namespace fsi
