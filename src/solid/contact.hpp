// The weak non-penetration constraint C_S ξ ≥ c_lb of SPEC §2 (paper eqs. 15, 21).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "mesh/mesh.hpp"
#include "solid/obstacle.hpp"

namespace fsi {

struct ContactConstraint {
  Eigen::SparseMatrix<double> C_S;  // rows: vertices strictly inside Γ_C; columns: 2nv dofs
  Eigen::VectorXd c_lb;
  std::vector<int> row_vertex;      // mesh vertex of each row
};

// (C_S)_ij = ∫_{Γ_C} (−ψ'(X1) φ_{j,1} + φ_{j,2}) φ_i ds,  (c_lb)_i = ∫_{Γ_C} (ψ(X1) − X2) φ_i ds,
// one row per vertex A_i strictly inside Γ_C (the ends of the Γ_C chain carry no row).
// ψ, ψ' are not polynomial: each edge is integrated by `gauss_points`-point Gauss
// (5 by default: 7e-10 relative error on the paper's arc, tests/solid/contact_test.cpp).
ContactConstraint assemble_contact(const Mesh& mesh, int gamma_c_label, const Foundation& psi,
                                   int gauss_points = 5);

}  // namespace fsi
