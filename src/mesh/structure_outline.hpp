// The structure's wetted boundary as one chain of vertices (fluid.method =
// "body-fitted"): the boundary off the clamped side Γ_D, from one end of Γ_D around
// the structure to the other. Its deformed positions are the inner boundary Γ_u of
// the body-fitted fluid mesh (gmsh_io.hpp, generate_fluid_mesh_around), where they are
// mesh vertices: match_vertices finds them there, so that nodal forces map one to one.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// The vertices of the boundary edges not labelled `clamped_label`, in order along
// them, from the end on Γ_D with the smaller y (then x) to the other end; so for a
// structure to the right of a clamped side on x = 0 the chain runs counter-clockwise
// (the structure on its left). Throws MeshError if those edges are not one simple
// path whose two ends lie on Γ_D.
std::vector<int> structure_outline(const Mesh& structure, int clamped_label);

// For each point, the vertex of `mesh` on the edges labelled `label` at that position
// (within `tolerance`); throws MeshError if a point has none, or two points share one.
std::vector<int> match_vertices(const Mesh& mesh, int label, const std::vector<Point>& points,
                                double tolerance);

}  // namespace fsi
