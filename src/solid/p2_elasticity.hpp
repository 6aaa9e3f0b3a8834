// The structure's operators on the P2 space (structure.element = "P2", SPEC §11):
// the same weak forms as P1 (eq. 16 and the hyperelastic f_int, K_T of
// hyperelastic.hpp) with the six quadratic basis functions per triangle and
// quadrature instead of P1's one point: degree 2 for A_S (∇N is linear), degree 4 for
// f_int and K_T (Saint-Venant–Kirchhoff's P(F) is cubic in ∇u; the neo-Hookean one,
// not a polynomial, is integrated to the same order). Dofs: dof(node, c) = c·n + node,
// n the number of nodes, as P1's paper ordering. Not yet used by the runs (issue 14).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/p2.hpp"
#include "solid/elasticity.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi {

SparseMatrix assemble_elasticity(const P2Space& space, const Lame& lame);
Eigen::VectorXd internal_force(const P2Space& space, const Material& m, const Eigen::VectorXd& u);
SparseMatrix tangent_stiffness(const P2Space& space, const Material& m, const Eigen::VectorXd& u);
// ∫ f·N_i (a rule exact to `degree`) and ∫_{label} h·N_i ds (`points`-point Gauss).
Eigen::VectorXd assemble_volume_load(const P2Space& space, const VectorField& f, int degree = 4);
Eigen::VectorXd assemble_surface_load(const P2Space& space, int label, const VectorField& h, int points = 3);
// Both components of every node on `label` (a clamped side).
std::vector<int> clamped_dofs(const P2Space& space, int label);

}  // namespace fsi
