// Reuse across the rows of a sweep: meshes (Gmsh at hF = 0.0025 takes ~3 s) and the
// structure and fluid setups (A_S and its factorisation, S = C A⁻¹Cᵀ; the fluid
// pattern, element loads and symbolic analysis). A row gets the same numbers as a
// run of its own: the caches hold only what the case's keys determine, and the fluid
// solver is reset (χ, last solution) and given the row's ε.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

class SetupCache {
 public:
  // Built or read on first use, then reused (all kept: meshes are small).
  const Mesh& structure_mesh(const Case& c);
  const Mesh& fluid_mesh(const Case& c);
  // The last setup of each kind is kept; a different key rebuilds it.
  StructureSetup& structure(const Case& c);
  FluidSetup& fluid(const Case& c);

  int hits = 0, misses = 0;

 private:
  std::map<std::string, Mesh> structure_meshes_, fluid_meshes_;
  std::string structure_key_, fluid_key_;
  StructureSetup structure_;
  FluidSetup fluid_;
};

// What determines a mesh / a setup, as text keys.
std::string structure_mesh_key(const Case& c);
std::string fluid_mesh_key(const Case& c);

}  // namespace fsi
