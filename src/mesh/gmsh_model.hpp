// The Gmsh side of the mesh layer: what runs inside the child process (gmsh_child.hpp).
// Each function does one piece of work on a fresh model and returns Gmsh's data
// unchecked; the child exits right after, so no model ever reaches the parent.
// Lengths are in the caller's units (gmsh_io.cpp scales them first).
#pragma once

#include <string>

#include "mesh/raw_mesh.hpp"

namespace fsi {

struct StructureGeometry;
struct FluidGeometry;
struct BodyFittedGeometry;
struct ScriptGeometry;

// gmsh::initialize, once per process, in the parent before the first fork: each
// child then starts from the same initialised, empty Gmsh. Initialising in every
// child instead cost 6 ms more per call (measured: 8.5 against 2.1 ms for fork,
// set-up and exit), most of it loading locales and rewriting FLTK's preference
// files (/etc/fltk/..., ~/.fltk/...), which Gmsh does on each initialisation.
// It starts no thread and installs no signal handler (measured).
void initialise_gmsh_once();

// Physical groups Omega_S (surface), Gamma_D, Gamma_C, Gamma_N (curves).
RawMesh mesh_structure_in_gmsh(const StructureGeometry& g);
// Physical groups D (surface), Sigma_1 ... Sigma_5 (curves).
RawMesh mesh_fluid_in_gmsh(const FluidGeometry& g);
// Physical groups D, Sigma_1 ... Sigma_5 (and Sigma_5_k per hole of FluidGeometry::holes)
// and Gamma_u (one line per outline segment).
RawMesh mesh_fluid_around_in_gmsh(const BodyFittedGeometry& g);
// A user's .geo script (ScriptGeometry, checked by geo_script.hpp) run with h
// predefined, meshed at h: its physical groups of dimension 1 and 2. Throws (as Gmsh
// does, a std::string) on the script's first error, an empty or non-planar geometry,
// or a bounding box that would need more than max_triangles triangles at h.
RawMesh mesh_script_in_gmsh(const ScriptGeometry& g);
// The file's physical groups of dimension 1 and 2, their elements, and Gmsh's
// warnings and "Skipping ..." notes (it skips duplicated nodes, measured).
RawMesh read_in_gmsh(const std::string& path);

}  // namespace fsi
