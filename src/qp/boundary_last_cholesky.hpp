// The sparse Cholesky factorisation of the QP's operator with the constrained dofs (the
// columns C touches: the contact boundary's) ordered last, so that the contact Schur
// complement S = C A⁻¹ Cᵀ comes from the factor's trailing block alone:
//     P A Pᵀ = L Lᵀ,  L = [L_II 0; L_GI L_GG],  P Cᵀ = [0; C_Gᵀ]
//     ⇒  L⁻¹ P Cᵀ = [0; W],  W = L_GG⁻¹ C_Gᵀ,  S = Wᵀ W,
// g × g and g × m dense work (g constrained dofs, m rows) instead of 2m triangular
// solves with the whole factor. Measured on the P2 §7.2 beam at hS = 0.75 mm (160k
// dofs, m = 267): those solves took 69 % of a run (perf), each Newton step about 13 s.
// Used for operators refactorised every Newton step (QpSolver::refactorise_often).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace fsi {

class BoundaryLastCholesky {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  // The ordering (AMD on the unconstrained dofs, then the columns of C with an entry)
  // and the symbolic analysis of A; then the numeric factorisation.
  void analyse(const SparseMatrix& A, const SparseMatrix& C);
  bool factorize(const SparseMatrix& A);  // false if A is not positive definite
  // Whether the analysis fits A's pattern and C touches only its constrained columns.
  bool fits(const SparseMatrix& A, const SparseMatrix& C) const;
  bool touches_only_constrained(const SparseMatrix& C) const;

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  // S = C A⁻¹ Cᵀ from the trailing block; C must touch only the constrained columns.
  Eigen::MatrixXd schur(const SparseMatrix& C) const;
  Eigen::Index factor_nonzeros() const { return llt_.matrixL().nestedExpression().nonZeros(); }

 private:
  SparseMatrix permuted(const SparseMatrix& A) const;
  std::vector<char> constrained_;  // per column of A
  int g_ = 0;                      // constrained dofs (the last g_ of the ordering)
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P_;  // old index → new
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> llt_;
  int rows_ = -1, nonzeros_ = -1;
};

}  // namespace fsi
