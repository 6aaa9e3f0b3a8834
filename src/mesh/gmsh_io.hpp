// Meshes from the Gmsh SDK: generated from the case geometry, or read from a
// user's .msh file whose physical groups name the boundary parts.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Ω_S0 = (0,L)×(0,H); boundary labels Gamma_D (x = 0), Gamma_C ((xc_min,xc_max)
// on y = 0, with vertices exactly at both ends), Gamma_N (the rest).
struct StructureGeometry {
  double L, H, xc_min, xc_max;
  double h;  // target element size
};
Mesh generate_structure_mesh(const StructureGeometry& g);

// D = (0,L1)×(−H2,H1) minus the disk B((x0,y0),r); labels Sigma_1 (left),
// Sigma_2 (bottom), Sigma_3 (right), Sigma_4 (top), Sigma_5 (circle).
struct FluidGeometry {
  double L1, H1, H2, x0, y0, r;
  double h;
};
Mesh generate_fluid_mesh(const FluidGeometry& g);

// Reads a Gmsh .msh file (format 4, or 2). The triangles are those of the physical
// surface `domain_group` (all triangles if the file has no such group); every name
// of `boundary_groups` must be a physical curve. Throws MeshError naming the file
// and what is wrong.
Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group);

}  // namespace fsi
