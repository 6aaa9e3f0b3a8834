// Meshes from the Gmsh SDK: generated from the case geometry (on request, and
// always around a deformed structure), from a user's .geo script, or read from a
// user's .msh file whose physical groups name the boundary parts. Every call into
// Gmsh runs in a child process (gmsh_child.hpp); what it sends back is built and
// checked here (mesh_builder.hpp, mesh_validation.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_geometry.hpp"

namespace fsi {

// Limits on one Gmsh call. The default time is generous: the largest mesh a case
// may ask for (4e6 fluid triangles) takes about 80 s (measured: 150k in 2.5 s).
struct GmshLimits {
  double seconds = 600;
};

// The generated meshes of mesh/generated_mesh.hpp made by Gmsh (the structure.mesher
// and fluid.mesher "gmsh"): Frontal-Delaunay with one smoothing pass, Delaunay
// without smoothing for a band refinement.
Mesh gmsh_structure_mesh(const StructureGeometry& g, const GmshLimits& limits = {});
Mesh gmsh_fluid_mesh(const FluidGeometry& g, const GmshLimits& limits = {});

// D minus the deformed structure (fluid.method = "body-fitted"): the box and its holes
// (the disk, or FluidGeometry::holes: [[obstacles]], SPEC §9) of `box` minus the
// polygon whose boundary is `outline` closed by the segment of x = 0 between its ends:
// the structure's boundary off its clamped side Γ_D, which lies on Σ1. Each outline
// segment is one mesh edge, so the outline's points are mesh vertices (the fluid's
// nodal forces map to the structure's vertices one to one);
// labels Sigma_1 (x = 0 above and below the structure) ... Sigma_5 (or Sigma_5_1, ...)
// as generate_fluid_mesh, and Gamma_u (the outline).
struct BodyFittedGeometry {
  FluidGeometry box;
  std::vector<Point> outline;  // from the end at x = 0 with the smaller y to the other
};
Mesh generate_fluid_mesh_around(const BodyFittedGeometry& g);
Mesh generate_fluid_mesh_around(const BodyFittedGeometry& g, const GmshLimits& limits);

// A user's Gmsh .geo script (structure.shape = "geo", SPEC §9): read and checked by
// geo_script.hpp, run in a child that can write no file and start no process, with
// the variable h = the case's size defined before its first line, and meshed with
// triangles of size at most h (Frontal-Delaunay as the generated meshes). Physical
// groups: the surface `domain_group`, the curves `boundary_groups` (each required)
// and `optional_groups` (labels, empty if the script has none). No unit scaling.
struct ScriptGeometry {
  std::string path, text;
  double h;
  double max_triangles;  // refused before meshing if the bounding box needs more
};
Mesh mesh_geo_script(const std::string& path, double h, double max_triangles,
                     const std::vector<std::string>& boundary_groups, const std::vector<std::string>& optional_groups,
                     const std::string& domain_group, const GmshLimits& limits = {});

// Reads a Gmsh .msh file (format 4, or 2; ASCII or binary). The triangles are those
// of the physical surface `domain_group`; every name of `boundary_groups` must be
// a physical curve of lines on the triangulation's boundary. Throws MeshError
// starting with the path and naming the defect (mesh_builder.hpp and
// mesh_validation.hpp list them).
Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group);
// `optional_groups`: curves that become labels (empty ones if absent).
Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group, const GmshLimits& limits,
                    const std::vector<std::string>& optional_groups = {});

}  // namespace fsi
