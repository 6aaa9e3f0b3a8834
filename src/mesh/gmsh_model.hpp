// The Gmsh side of the mesh layer, a plugin: libfsicontact_gmsh.so (gmsh_plugin.cpp)
// links the Gmsh SDK and is loaded (dlopen) the first time a run needs Gmsh — a .geo
// script, a .msh file, a body-fitted fluid mesh, a mesher = "gmsh" — so that the
// runs that do not, most of them, do not pay for loading it: 0.2 s, measured
// (docs/performance.md, "Start-up": libgmsh and its OpenCASCADE libraries bind all
// their symbols at load).
//
// Each function does one piece of work on a fresh model in a child process
// (gmsh_child.hpp) and returns Gmsh's data unchecked; the child exits right after, so
// no model ever reaches the parent. Lengths are in the caller's units (gmsh_io.cpp
// scales them first). Gmsh 4.8 throws its errors as std::string.
#pragma once

#include <string>

#include "mesh/raw_mesh.hpp"

namespace fsi {

struct StructureGeometry;
struct FluidGeometry;
struct BodyFittedGeometry;
struct ScriptGeometry;

struct GmshPlugin {
  // Must equal kGmshPluginVersion: the loader refuses a plugin of another build.
  int version;
  // gmsh::initialize, once per process, in the parent before the first fork: each
  // child then starts from the same initialised, empty Gmsh ("" or the error).
  std::string (*initialise)();
  // Physical groups Omega_S (surface), Gamma_D, Gamma_C, Gamma_N (curves).
  RawMesh (*mesh_structure)(const StructureGeometry& g);
  // Physical groups D (surface), Sigma_1 ... Sigma_5 (curves; Sigma_5_k per hole).
  RawMesh (*mesh_fluid)(const FluidGeometry& g);
  // The same and Gamma_u (one line per outline segment).
  RawMesh (*mesh_fluid_around)(const BodyFittedGeometry& g);
  // A user's .geo script run with h predefined, meshed at h: its physical groups of
  // dimension 1 and 2. `fence` is called once the script is in memory, before Gmsh
  // runs it (gmsh_child.hpp, forbid_side_effects). Throws on the script's first
  // error, an empty or non-planar geometry, or a bounding box that would need more
  // than max_triangles triangles at h.
  RawMesh (*mesh_script)(const ScriptGeometry& g, void (*fence)());
  // The file's physical groups of dimension 1 and 2, their elements, and Gmsh's
  // warnings and "Skipping ..." notes (it skips duplicated nodes, measured).
  RawMesh (*read)(const std::string& path);
};
inline constexpr int kGmshPluginVersion = 1;

// The plugin, loaded and Gmsh initialised on the first call; throws SolverFailure naming
// the library if it cannot be loaded.
const GmshPlugin& gmsh_plugin();

}  // namespace fsi
