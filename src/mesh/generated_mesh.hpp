// The meshes a case gives by numbers: the structure's rectangle and the fluid box with
// its holes, made by the project's generator (mesh/lattice_mesher.hpp) or, on request,
// by Gmsh (mesh/gmsh_io.hpp: the program's meshes before, kept to reproduce them).
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_geometry.hpp"

namespace fsi {

// Who makes a generated mesh (the case keys structure.mesher and fluid.mesher).
enum class MeshGenerator { lattice, gmsh };
// "lattice" | "gmsh"; throws std::invalid_argument naming the allowed values.
MeshGenerator mesh_generator(const std::string& name);

// The labels of D's holes in a mesh of generate_fluid_mesh or a file: Sigma_5_1,
// Sigma_5_2, ... if there are any, else Sigma_5 (none for a box without holes).
std::vector<int> hole_labels(const Mesh& mesh);

// Throw MeshError if the mesh cannot be made.
Mesh generate_structure_mesh(const StructureGeometry& g, MeshGenerator by = MeshGenerator::lattice);
Mesh generate_fluid_mesh(const FluidGeometry& g, MeshGenerator by = MeshGenerator::lattice);

}  // namespace fsi
