#include "qp/active_set_solver.hpp"

#include <algorithm>

#include <cstdio>
#include <set>

namespace fsi {
namespace {

std::vector<int> indices_of(const std::vector<bool>& mask) {
  std::vector<int> idx;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) idx.push_back(static_cast<int>(i));
  return idx;
}

// The start: the warm result's active set if it has one of the right size, else the
// rows violated at α = 0 (slack d < 0).
std::vector<bool> initial_active_set(const Eigen::VectorXd& d, const QpResult* warm) {
  const Eigen::Index m = d.size();
  std::vector<bool> active(m, false);
  if (warm && warm->active.size() == static_cast<std::size_t>(m))
    active = warm->active;
  else
    for (Eigen::Index i = 0; i < m; ++i) active[i] = d[i] < 0;
  return active;
}

}  // namespace

void ActiveSetSolver::set_operator(const SparseMatrix& A, const SparseMatrix& C) {
  if (A.rows() != A.cols() || C.cols() != A.rows())
    throw QpError("active-set: operator and constraint sizes do not match");
  require_finite(A, "active-set", "the operator A_S");
  require_finite(C, "active-set", "the constraint matrix C_S");
  S_.resize(0, 0);  // S = C A⁻¹ Cᵀ belongs to the old A: set_constraints recomputes it
  // The same pattern as before (a Newton step's tangent, SPEC §11): the symbolic
  // analysis is kept and only the numeric factorisation redone.
  const bool same_pattern = factorised() && A.nonZeros() == A_.nonZeros() && A.rows() == A_.rows() &&
                            std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1, A_.outerIndexPtr()) &&
                            std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), A_.innerIndexPtr());
  A_ = A;
  bool ok = false;
  if (refactorise_often) {
    cholesky_.reset();
    if (!(same_pattern && simplicial_ && simplicial_->fits(A_, C))) {
      simplicial_ = std::make_unique<BoundaryLastCholesky>();
      simplicial_->analyse(A_, C);
    }
    ok = simplicial_->factorize(A_);
  } else {
    simplicial_.reset();
    if (same_pattern && cholesky_) {
      cholesky_->factorize(A_);
    } else {
      cholesky_ = std::make_unique<Eigen::CholmodSupernodalLLT<SparseMatrix>>();
      cholesky_->compute(A_);
    }
    ok = cholesky_->info() == Eigen::Success;
  }
  if (!ok)
    throw QpError("active-set: Cholesky factorisation of A_S failed (not positive definite: "
                  "is the structure clamped?)");
  set_constraints(C);
}

namespace {
// Same size, pattern and values (both compressed, as Eigen's products leave them).
bool same_matrix(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  if (!a.isCompressed() || !b.isCompressed()) return false;
  const auto n = static_cast<std::size_t>(a.nonZeros());
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + n, b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + n, b.valuePtr());
}
}  // namespace

void ActiveSetSolver::set_constraints(const SparseMatrix& C) {
  if (!factorised()) throw QpError("active-set: set_constraints before set_operator");
  if (C.cols() != A_.rows()) throw QpError("active-set: constraint and operator sizes do not match");
  require_finite(C, "active-set", "the constraint matrix C_S");
  // The same C again (a half-plane's rows, re-linearised about each time step's state,
  // do not change): S is kept. Measured on the bar impact (2 600 dofs, 440 rows): the
  // 440 solves of S took 44 ms of a 45 ms step; the comparison takes 10 µs.
  if (S_.rows() == C.rows() && same_matrix(C_, C)) return;
  C_ = C;
  const Eigen::Index m = C_.rows();
  if (simplicial_ && simplicial_->touches_only_constrained(C_)) {
    S_ = simplicial_->schur(C_);  // from the factor's trailing block (boundary_last_cholesky.hpp)
  } else {
    compute_schur_by_solves();
  }
  S_ = 0.5 * (S_ + S_.transpose()).eval();  // symmetric to round-off
  kappa_ = S_.diagonal().cwiseInverse();
  if (m > 0 && !(S_.diagonal().minCoeff() > 0))
    throw QpError("active-set: a contact row has no free degree of freedom");
}

// S = C A⁻¹ Cᵀ by blocks of columns, so A⁻¹Cᵀ is never stored whole.
void ActiveSetSolver::compute_schur_by_solves() {
  const Eigen::Index m = C_.rows();
  S_.resize(m, m);
  const SparseMatrix Ct = C_.transpose();
  constexpr Eigen::Index block = 64;
  for (Eigen::Index j0 = 0; j0 < m; j0 += block) {
    const Eigen::Index nb = std::min(block, m - j0);
    const Eigen::MatrixXd rhs = Eigen::MatrixXd(Ct.middleCols(j0, nb));
    const Eigen::MatrixXd Z = solve_A<Eigen::MatrixXd>(rhs);
    S_.middleCols(j0, nb) = C_ * Z;
  }
}

Eigen::VectorXd ActiveSetSolver::solve_active(const std::vector<bool>& active,
                                              const Eigen::VectorXd& d) const {
  const std::vector<int> idx = indices_of(active);
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(d.size());
  if (idx.empty()) return alpha;
  const Eigen::MatrixXd S_AA = S_(idx, idx);
  Eigen::LLT<Eigen::MatrixXd> llt(S_AA);
  if (llt.info() != Eigen::Success) throw QpError("active-set: contact rows are dependent");
  const Eigen::VectorXd d_A = d(idx);
  const Eigen::VectorXd alpha_A = llt.solve(-d_A);
  alpha(idx) = alpha_A;
  return alpha;
}

// Lawson–Hanson for min ½αᵀSα + dᵀα, α ≥ 0 (NNLS in normal-equation form):
// finite, monotone, never cycles.
Eigen::VectorXd ActiveSetSolver::lawson_hanson(const Eigen::VectorXd& d, int& iterations) const {
  const Eigen::Index m = d.size();
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(m);
  std::vector<bool> passive(m, false);
  const double tol = 1e-14 * std::max(d.lpNorm<Eigen::Infinity>(), 1e-300);
  Eigen::VectorXd w = d;
  for (int outer = 0; outer < 3 * m + 10; ++outer) {
    Eigen::Index j = -1;
    double most_negative = -tol;
    for (Eigen::Index i = 0; i < m; ++i)
      if (!passive[i] && w[i] < most_negative) most_negative = w[i], j = i;
    if (j < 0) break;
    passive[j] = true;
    for (int inner = 0; inner < 3 * m + 10; ++inner) {
      ++iterations;
      const Eigen::VectorXd s = solve_active(passive, d);
      bool positive = true;
      for (Eigen::Index i = 0; i < m; ++i)
        if (passive[i] && s[i] <= 0) positive = false;
      if (positive) {
        alpha = s;
        break;
      }
      double theta = 1.0;
      for (Eigen::Index i = 0; i < m; ++i)
        if (passive[i] && s[i] <= 0) theta = std::min(theta, alpha[i] / (alpha[i] - s[i]));
      alpha += theta * (s - alpha);
      for (Eigen::Index i = 0; i < m; ++i)
        if (passive[i] && alpha[i] <= 1e-300) passive[i] = false, alpha[i] = 0;
    }
    w = d + S_ * alpha;
  }
  return alpha;
}

// PDAS from result.active (the set update of the header: A = {α_i − κ_i w_i > 0}),
// alpha the multipliers of the last set solved. True when the set no longer changes;
// false when it cycles or max_iterations is reached.
bool ActiveSetSolver::primal_dual_active_set(const Eigen::VectorXd& d, QpResult& result,
                                             Eigen::VectorXd& alpha) const {
  const Eigen::Index m = C_.rows();
  bool converged = m == 0;
  std::set<std::vector<bool>> visited{result.active};
  while (!converged && result.iterations < max_iterations) {
    ++result.iterations;
    alpha = solve_active(result.active, d);
    const Eigen::VectorXd w = d + S_ * alpha;
    std::vector<bool> next(m);
    int changed = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      next[i] = alpha[i] - kappa_[i] * w[i] > 0;
      changed += next[i] != result.active[i];
    }
    if (progress) {
      char line[160];
      std::snprintf(line, sizeof line, "active-set it %3d: %d active of %d, %d changed",
                    result.iterations, static_cast<int>(indices_of(next).size()),
                    static_cast<int>(m), changed);
      progress(line);
    }
    if (changed == 0) {
      converged = true;
    } else if (!visited.insert(next).second) {
      break;  // cycling: hand over to Lawson–Hanson
    } else {
      result.active = next;
    }
  }
  return converged;
}

// The multipliers by Lawson–Hanson when PDAS did not converge; result.active: the
// rows active or degenerate (w ≤ 0) at them.
Eigen::VectorXd ActiveSetSolver::lawson_hanson_fallback(const Eigen::VectorXd& d, QpResult& result) {
  const Eigen::Index m = C_.rows();
  used_fallback_ = true;
  const Eigen::VectorXd alpha = lawson_hanson(d, result.iterations);
  const Eigen::VectorXd w = d + S_ * alpha;
  for (Eigen::Index i = 0; i < m; ++i) result.active[i] = alpha[i] > 0 || w[i] <= 0;
  if (progress) progress("active-set: cycling detected, finished by Lawson-Hanson");
  return alpha;
}

QpResult ActiveSetSolver::solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                                const QpResult* warm) {
  if (!factorised()) throw QpError("active-set: solve before set_operator");
  if (b.size() != A_.rows() || c.size() != C_.rows())
    throw QpError("active-set: load or bound has the wrong size");
  require_finite(b, "active-set", "the load b_S");
  require_finite(c, "active-set", "the bound c_lb");
  used_fallback_ = false;
  const Eigen::Index m = C_.rows();
  const Eigen::VectorXd d = C_ * solve_A<Eigen::VectorXd>(b) - c;  // slack at α = 0

  QpResult result;
  result.active = initial_active_set(d, warm);
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(m);
  if (!primal_dual_active_set(d, result, alpha)) alpha = lawson_hanson_fallback(d, result);
  result.alpha = alpha.cwiseMax(0.0);
  result.x = solve_A<Eigen::VectorXd>(b + C_.transpose() * result.alpha);
  result.kkt = solver_kkt_residuals(A_, b, C_, c, result.x, alpha);
  result.status = used_fallback_ ? "converged (Lawson-Hanson fallback)" : "converged";
  if (!(result.kkt.max() <= kkt_tolerance))
    throw QpError("active-set: KKT residual " + format_kkt(result.kkt) +
                  " above tolerance after " + std::to_string(result.iterations) + " iterations");
  return result;
}

}  // namespace fsi
