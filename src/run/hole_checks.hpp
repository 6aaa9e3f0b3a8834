// A user's fluid mesh (fluid.mesh) with [[obstacles]] (SPEC §9, §10 "Box sides"):
// every obstacle of the case is a hole of D, named Sigma_5 (one obstacle) or Sigma_5_1
// ... Sigma_5_n in the case's order, so that obstacles[i].force is that obstacle's.
// Each defect is an input error naming the case file, fluid.mesh and the hole.
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// The physical curves to read as D's holes: Sigma_5 and Sigma_5_1 for one obstacle
// (either may name it), Sigma_5_1 ... Sigma_5_n for n.
std::vector<std::string> mesh_hole_groups(const Case& c);

// One obstacle's hole named Sigma_5 in the file becomes Sigma_5_1, as the generated
// box names it (hole_labels and the forces then read one name).
void name_mesh_holes(const Case& c, Mesh& mesh);

// Each obstacle's hole present, its edges on the obstacle's boundary (a circle's
// vertices on the circle; a polygon's edges on its sides, so its corners are vertices),
// and no triangle of D inside an obstacle.
void check_mesh_holes(const Case& c, const Mesh& mesh);

}  // namespace fsi
