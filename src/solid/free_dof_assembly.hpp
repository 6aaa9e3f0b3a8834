// The hyperelastic internal force and tangent assembled straight onto the free dofs
// (Dirichlet dofs eliminated), into the fixed sparsity of A_S's free block: what each
// Newton step (SPEC §11) needs, without triplets or selection products. Measured on the
// §7.2 beam (154 dofs): the triplet assembly and Pᵀ K P took about half of a step.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "fem/p1.hpp"
#include "mesh/mesh.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi {

class FreeDofAssembler {
 public:
  // `free_dofs`: the free dofs in increasing order (reduced index k ↔ free_dofs[k]);
  // `pattern`: a matrix on them with every free–free coupling of the mesh (A_S's).
  FreeDofAssembler(const Mesh& mesh, const std::vector<int>& free_dofs, const SparseMatrix& pattern);

  // f_int(u) on the free dofs (u on all 2nv dofs). Throws SolverFailure for an
  // inverted triangle with the neo-Hookean model.
  Eigen::VectorXd force(const Material& m, const Eigen::VectorXd& u) const;
  // K_T(u) on the free dofs, written into K's values (K: a copy of `pattern`).
  void tangent(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const;

 private:
  Matrix2 gradient(int t, const Eigen::VectorXd& u) const;

  const Mesh& mesh_;
  std::vector<P1Triangle> geometry_;
  std::vector<int> reduced_;  // 2nv dof → reduced index, −1 if fixed
  std::vector<int> slot_;     // 36 per triangle: (a c, b d) → position in K's values, −1 if fixed
};

}  // namespace fsi
