// Reuse across the rows of a sweep: meshes (Gmsh at hF = 0.0025 takes ~3 s) and the
// structure and fluid setups (A_S and its factorisation, S = C A⁻¹Cᵀ; the fluid
// pattern, element loads and symbolic analysis). A row gets the same numbers as a
// run of its own: each cache is keyed by the whole of the case sections its builder
// reads (their JSON, which summary.json's "parameters" prints too, so a key cannot
// be forgotten in one and not the other), the mesh checks against the case run for
// every row, and the fluid solver is reset (χ, last solution) and given the row's ε.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <memory>
#include <string>

#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

class SetupCache {
 public:
  // Built or read on first use, then reused (all kept: meshes are small); checked
  // against `c` on every call.
  const Mesh& structure_mesh(const Case& c);
  const Mesh& fluid_mesh(const Case& c);
  // The last setup of each kind is kept; a different key rebuilds it.
  StructureSetup& structure(const Case& c);
  FluidSetup& fluid(const Case& c);
  // fluid.h_near's box (run/fluid_band.hpp), computed once per structure setup.
  std::optional<std::array<double, 4>> band(const Case& c);

 private:
  std::map<std::string, Mesh> structure_meshes_, fluid_meshes_;
  std::map<std::string, std::array<double, 4>> bands_;
  std::string structure_key_, fluid_key_;
  StructureSetup structure_;
  FluidSetup fluid_;
};

// What determines each mesh / setup, as text keys.
std::string structure_mesh_key(const Case& c);
std::string fluid_mesh_key(const Case& c);
std::string structure_setup_key(const Case& c);
std::string fluid_setup_key(const Case& c);

}  // namespace fsi
