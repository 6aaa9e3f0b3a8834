// Is a Mesh a planar triangulation the solver can use? Orientation, shape and
// topology checks for a mesh built from Gmsh's data (mesh_builder.hpp), generated
// or read from a user's file.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/mesh_builder.hpp"

namespace fsi {

// Makes the triangles counter-clockwise, turning each surface entity as a whole
// (a surface whose normal is −z is clockwise throughout), and throws MeshError
// naming the first defect, by Gmsh's tags:
//  - a triangle that repeats a node or has zero area (relative to its longest edge²);
//  - a surface with both clockwise and counter-clockwise triangles (tangled);
//  - an edge of more than two triangles, or two triangles on the same side of their
//    common edge (a fold or an overlap);
//  - triangles turning more than once around a node (a fold with all areas positive);
//  - a boundary line whose nodes belong to no triangle, that is no edge of the
//    triangulation, lies inside it (two triangles), or appears twice.
void orient_and_validate(Mesh& mesh, const MeshOrigin& origin);

}  // namespace fsi
