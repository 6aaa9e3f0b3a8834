// The fluid's load on the structure from a body-fitted fluid solution (fluid.method =
// "body-fitted"). The fluid mesh has the deformed outline's points as vertices
// (mesh/structure_outline.hpp), so the nodal forces −R of the residual method
// (fluid/stokes_residual.hpp) at them are the load at the structure's outline
// vertices, node to node: the traces of the fluid's and the structure's P1 basis
// functions on Γ_u are the same functions.
//
// Like eq. (33), the load acts on the reference configuration of the linear structure:
// the pressure's share is applied with the reference normal N,
//     b = −R − P(φ(X)) + P(X),   P(x)_k = −∫ p φ_k n ds along the polyline x,
// where P(φ(X)) is the deformed-normal pressure force that −R holds and P(X) the
// same pressure values (p∘φ, as eq. 33's p̃) on the reference outline: the viscous
// share stays that of the deformed, body-fitted mesh. Applied with the deformed normal,
// the pressure level (about −500 Pa at the §7.2 beam) becomes a follower load close to
// the linear beam's buckling load, which a linear structure has no geometric stiffness
// to meet: the relaxed fixed point diverged or landed on a spurious upward state
// (measured before this code, issue 12's notes; docs/theory.md, "The body-fitted check").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

enum class PressureNormal { reference, deformed };

// −∫ p φ_k n ds along the polyline `points` (P1 pressure, values `p` at the points),
// n the right-hand normal (the outward normal of a structure on the polyline's left).
// Column k: the force at points[k]. Exact: ∫ p φ_k on a segment in closed form (both linear).
Eigen::Matrix2Xd pressure_nodal_forces(const std::vector<Point>& points, const Eigen::VectorXd& p);

// The load on the structure (2nv, paper ordering) from the residual at the fluid nodes
// of the outline (column k: vertex outline[k]) and the fluid pressure there; `u` the
// displacement the fluid mesh was made for.
Eigen::VectorXd body_fitted_load(const Mesh& reference, const std::vector<int>& outline,
                                 const Eigen::Matrix2Xd& residual, const Eigen::VectorXd& pressure,
                                 const Eigen::VectorXd& u, PressureNormal normal);

}  // namespace fsi
