// Meshes from the Gmsh SDK: generated from the case geometry, or read from a
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

namespace fsi {

// Limits on one Gmsh call. The default time is generous: the largest mesh a case
// may ask for (4e6 fluid triangles) takes about 80 s (measured: 150k in 2.5 s).
struct GmshLimits {
  double seconds = 600;
};

// Ω_S0 = (0,L)×(0,H); boundary labels Gamma_D (x = 0), Gamma_C ((xc_min,xc_max)
// on y = 0, with vertices exactly at both ends), Gamma_N (the rest).
struct StructureGeometry {
  double L, H, xc_min, xc_max;
  double h;  // target element size
};
Mesh generate_structure_mesh(const StructureGeometry& g);
Mesh generate_structure_mesh(const StructureGeometry& g, const GmshLimits& limits);

// D = (0,L1)×(−H2,H1) minus the disk B((x0,y0),r) (or minus `holes`); labels Sigma_1
// (left), Sigma_2 (bottom), Sigma_3 (right), Sigma_4 (top), Sigma_5 (circle; or
// Sigma_5_1, Sigma_5_2, ... the holes).
//
// With h_near > 0, triangles of size h_near inside the box `band` ([x_min, y_min,
// x_max, y_max]), growing linearly by kBandGrowth per unit distance from it up to h
// (a Gmsh Box field with a transition thickness): the band refinement of fluid.h_near.
// A hole of D: the disk B((x0, y0), r), or the polygon `corners` (a simple one, either
// orientation) if it has any. A polygon's boundary is a loop of mesh edges through its
// corners, each side cut into at least two (mesh_fluid_in_gmsh).
struct FluidHole {
  double x0 = 0, y0 = 0, r = 0;
  std::vector<Point> corners = {};
};

struct FluidGeometry {
  double L1, H1, H2, x0, y0, r;
  double h;
  double h_near = 0;
  std::array<double, 4> band{};
  // [[obstacles]] (SPEC §9): these disks and polygons, any number, are D's holes
  // instead of the one above, labelled Sigma_5_1, Sigma_5_2, ... in this order (their
  // union is Σ5; Gmsh's model also has it as the group Sigma_5).
  std::optional<std::vector<FluidHole>> holes = std::nullopt;
};
// The labels of D's holes in a mesh of generate_fluid_mesh or a file: Sigma_5_1,
// Sigma_5_2, ... if there are any, else Sigma_5 (none for a box without holes).
std::vector<int> hole_labels(const Mesh& mesh);
// The size's growth away from the band, per unit length. Measured on §7.2 (docs/
// validation.md, "Band refinement"): halving it or the far size h moves max |u| by
// under 0.5 µm at h_near = 0.001, while the triangle count stays within 10 % of the
// band's own.
inline constexpr double kBandGrowth = 0.2;
Mesh generate_fluid_mesh(const FluidGeometry& g);
Mesh generate_fluid_mesh(const FluidGeometry& g, const GmshLimits& limits);

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
