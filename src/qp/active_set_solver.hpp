// Primal–dual active-set (semismooth Newton) solver for the contact QP.
//
// A_S is factorised once by sparse Cholesky (CHOLMOD). Eliminating x from the KKT
// system leaves a linear complementarity problem in the multipliers α ∈ R^m:
//     w = S α + d ≥ 0,  α ≥ 0,  αᵀw = 0,   S = C A⁻¹ Cᵀ,  d = C A⁻¹ b − c,
// where w = Cx − c is the constraint slack. The active-set step (α_I = 0, w_A = 0)
// is exactly the PDAS step of the full KKT system, solved on the small dense S
// (m = contact rows, tens to hundreds) instead of refactorising the saddle-point
// matrix each iteration. The set update follows deal.II step-41:
//     A = { i : α_i − κ_i w_i > 0 },  κ_i = 1/S_ii,
// and stops when the set no longer changes (then the KKT conditions hold exactly).
// PDAS converges from a good start but can cycle on non-M-matrices; if it does, the
// finite Lawson–Hanson active-set method on the same LCP finishes the solve.
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <memory>

#include "qp/boundary_last_cholesky.hpp"
#include "qp/qp_problem.hpp"

namespace fsi {

class ActiveSetSolver final : public QpSolver {
 public:
  void set_operator(const SparseMatrix& A, const SparseMatrix& C) override;
  void set_constraints(const SparseMatrix& C) override;
  QpResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                 const QpResult* warm = nullptr) override;
  std::string name() const override { return "active-set"; }

  int max_iterations = 100;
  // Whether the last solve needed the Lawson–Hanson fallback.
  bool used_fallback() const { return used_fallback_; }

 private:
  Eigen::VectorXd solve_active(const std::vector<bool>& active, const Eigen::VectorXd& d) const;
  Eigen::VectorXd lawson_hanson(const Eigen::VectorXd& d, int& iterations) const;
  bool primal_dual_active_set(const Eigen::VectorXd& d, QpResult& result, Eigen::VectorXd& alpha) const;
  Eigen::VectorXd lawson_hanson_fallback(const Eigen::VectorXd& d, QpResult& result);
  void compute_schur_by_solves();

  SparseMatrix A_, C_;
  // LLᵀ, not CHOLMOD's automatic choice: its LDLᵀ accepts negative pivots, and A_S
  // must be positive definite.
  std::unique_ptr<Eigen::CholmodSupernodalLLT<SparseMatrix>> cholesky_;
  std::unique_ptr<BoundaryLastCholesky> simplicial_;  // refactorise_often
  bool factorised() const { return cholesky_ || simplicial_; }
  // A⁻¹ rhs by whichever factorisation is in use.
  template <class Plain>
  Plain solve_A(const Plain& rhs) const {
    return simplicial_ ? simplicial_->solve(rhs) : Plain(cholesky_->solve(rhs));
  }
  Eigen::MatrixXd S_;
  Eigen::VectorXd kappa_;
  bool used_fallback_ = false;
};

}  // namespace fsi
