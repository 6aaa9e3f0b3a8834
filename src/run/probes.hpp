// Quantities of a structure state read at given places: the P1 displacement at a
// point of the reference configuration, and the resultant of a nodal load.
#pragma once

#include <Eigen/Core>

#include "mesh/mesh.hpp"

namespace fsi {

// u (2nv, paper ordering) interpolated at the reference point X (the nearest point of
// the mesh if X is outside it).
Point displacement_at(const Mesh& reference, const Eigen::VectorXd& u, const Point& X);

// [Σ F_x, Σ F_y] of a nodal load vector (2nv): tested with w = e_x, e_y, the force
// the load's integrals carry (eq. 33's fluid terms: the fluid's force on the structure).
Point resultant(const Eigen::VectorXd& load);

}  // namespace fsi
