#include "qp/ipopt_solver.hpp"

#include <IpException.hpp>
#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <cmath>
#include <cstdio>
#include <new>
#include <utility>

namespace fsi {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// How the QP is scaled for IPOPT, x = ℓ y:
//     min ½ yᵀ Â y − b̂ᵀ y  s.t.  Ĉ y ≥ ĉ,   Â = A / a,  b̂ = b / (ℓ a),  Ĉ = C / γ,  ĉ = c / (ℓ γ),
// a = max|A_ij|, γ = max|C_ij| (the objective divided by ℓ² a, the constraints by ℓ γ).
// IPOPT's absolute tolerances (constr_viol_tol, dual_inf_tol) assume y, b̂ and ĉ of
// order one at most: the raw contact QP has displacements of 1e-3 m and constraint
// values of 1e-6 m². ℓ ≥ ‖b‖∞ / a makes ‖b̂‖∞ ≤ 1 and ℓ ≥ max_i |c_i| / Σ_j |C_ij|
// makes |ĉ_i| ≤ 1 (see displacement_scale).
struct Scaling {
  double length = 1;  // ℓ
  double a_max = 1;   // a
  double c_max = 1;   // γ
  // α = λ̂ ℓ a / γ: the scaled stationarity ∇f/(ℓ a) = Cᵀλ̂/γ, unscaled.
  double multiplier() const { return length * a_max / c_max; }
};

class ContactTnlp final : public Ipopt::TNLP {
 public:
  ContactTnlp(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
              const Eigen::VectorXd& c, const Eigen::VectorXd* x0, const Scaling& scaling,
              std::function<void(const std::string&)> progress)
      : A_full_(A / scaling.a_max),
        C_(C / scaling.c_max),
        b_(b / (scaling.length * scaling.a_max)),
        c_(c / (scaling.length * scaling.c_max)),
        scaling_(scaling),
        progress_(std::move(progress)) {
    A_ = A_full_.triangularView<Eigen::Lower>();
    A_.makeCompressed();
    C_.makeCompressed();
    if (x0 && x0->allFinite()) y0_ = *x0 / scaling.length;
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = static_cast<Index>(A_.rows());
    m = static_cast<Index>(C_.rows());
    nnz_jac = static_cast<Index>(C_.nonZeros());
    nnz_h = static_cast<Index>(A_.nonZeros());
    style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    for (Index i = 0; i < n; ++i) x_l[i] = -2e19, x_u[i] = 2e19;
    for (Index i = 0; i < m; ++i) g_l[i] = c_[i], g_u[i] = 2e19;
    return true;
  }
  bool get_starting_point(Index n, bool init_x, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    if (init_x)
      for (Index i = 0; i < n; ++i) x[i] = y0_.size() == n ? y0_[i] : 0.0;
    return true;
  }
  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    const Eigen::Map<const Eigen::VectorXd> y(x, n);
    f = 0.5 * y.dot(A_full_ * y) - b_.dot(y);
    return true;
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    const Eigen::Map<const Eigen::VectorXd> y(x, n);
    Eigen::Map<Eigen::VectorXd>(g, n) = A_full_ * y - b_;
    return true;
  }
  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    const Eigen::Map<const Eigen::VectorXd> y(x, n);
    Eigen::Map<Eigen::VectorXd>(g, m) = C_ * y;
    return true;
  }
  bool eval_jac_g(Index, const Number*, bool, Index, Index, Index* rows, Index* cols,
                  Number* values) override {
    return triplets(C_, rows, cols, values, 1.0);
  }
  bool eval_h(Index, const Number*, bool, Number obj_factor, Index, const Number*, bool, Index,
              Index* rows, Index* cols, Number* values) override {
    return triplets(A_, rows, cols, values, obj_factor);  // constraints are linear
  }
  bool intermediate_callback(Ipopt::AlgorithmMode mode, Index iter, Number obj, Number inf_pr,
                             Number inf_du, Number mu, Number, Number, Number, Number, Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    // IPOPT 3.11 with the Mehrotra predictor-corrector dereferences the affine step,
    // which its restoration phase never computes (coin-or/Ipopt#114: an assertion in
    // debug builds, a segfault in Debian's): stop at the restoration phase's first
    // iteration, which is reported here before its first search direction.
    if (mode == Ipopt::RestorationPhaseMode) {
      entered_restoration_ = true;
      return false;
    }
    if (progress_) {
      char line[160];
      std::snprintf(line, sizeof line, "ipopt it %3d: objective %.6e, primal inf %.1e, dual inf %.1e, mu %.1e",
                    static_cast<int>(iter), obj, inf_pr, inf_du, mu);
      progress_(line);
    }
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index m, const Number*, const Number* lambda, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    status_ = status;
    x_ = Eigen::Map<const Eigen::VectorXd>(x, n) * scaling_.length;
    // IPOPT's Lagrangian is f + λᵀg: λ ≤ 0 on a lower bound, so α = −λ, unscaled.
    alpha_ = -Eigen::Map<const Eigen::VectorXd>(lambda, m) * scaling_.multiplier();
  }

  Ipopt::SolverReturn status_ = Ipopt::INTERNAL_ERROR;
  Eigen::VectorXd x_, alpha_;  // alpha_: IPOPT's multipliers, unscaled, not clamped
  bool entered_restoration_ = false;

 private:
  static bool triplets(const SparseMatrix& M, Index* rows, Index* cols, Number* values,
                       double factor) {
    Index k = 0;
    for (Eigen::Index j = 0; j < M.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(M, j); it; ++it, ++k) {
        if (values)
          values[k] = factor * it.value();
        else
          rows[k] = static_cast<Index>(it.row()), cols[k] = static_cast<Index>(it.col());
      }
    return true;
  }

  SparseMatrix A_, A_full_, C_;  // Â (lower triangle, for the Hessian), Â, Ĉ
  Eigen::VectorXd b_, c_, y0_;   // b̂, ĉ, the starting point (empty: 0)
  Scaling scaling_;
  std::function<void(const std::string&)> progress_;
};

// ℓ, the larger of two displacement scales: the gap the constraints must close,
// max_i |c_i| / Σ_j |C_ij|, and the displacement a node sees under the largest load,
// ‖b‖∞ / max|A_ij|. The gap alone (as before) left a load-dominated problem
// (E = 1e-300 Pa) with b̂ ~ 1e301: IPOPT's objective overflowed and its restoration
// phase crashed. QpError if ℓ, ℓ a or ℓ γ is not a positive double: the problem's
// solution or its scaled data would not be representable.
Scaling displacement_scale(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
                           const Eigen::VectorXd& c) {
  Scaling s;
  s.a_max = A.nonZeros() ? A.coeffs().cwiseAbs().maxCoeff() : 0.0;
  if (!(s.a_max > 0)) throw QpError("ipopt: the operator A_S is zero");
  s.c_max = C.nonZeros() ? C.coeffs().cwiseAbs().maxCoeff() : 1.0;
  double gap = 0;
  if (C.nonZeros() && c.size()) {
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(C.rows());
    for (Eigen::Index j = 0; j < C.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(C, j); it; ++it) row_sums[it.row()] += std::abs(it.value());
    for (Eigen::Index i = 0; i < C.rows(); ++i)
      if (row_sums[i] > 0) gap = std::max(gap, std::abs(c[i]) / row_sums[i]);
  }
  const double load = b.size() ? b.lpNorm<Eigen::Infinity>() / s.a_max : 0.0;
  s.length = std::max(gap, load);
  if (s.length == 0) s.length = 1.0;  // no load, no gap: x = 0
  const auto representable = [](double v) { return std::isfinite(v) && v > 0; };
  if (!representable(s.length) || !representable(s.length * s.a_max) ||
      !representable(s.length * s.c_max)) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "ipopt: the problem cannot be scaled in double precision (gap scale %.3g, "
                  "load scale %.3g, max|A| %.3g, max|C| %.3g)",
                  gap, load, s.a_max, s.c_max);
    throw QpError(text);
  }
  return s;
}

// IPOPT's return status in words, for messages.
std::string status_text(Ipopt::ApplicationReturnStatus status) {
  static const std::pair<Ipopt::ApplicationReturnStatus, const char*> words[] = {
      {Ipopt::Solve_Succeeded, "solved"},
      {Ipopt::Solved_To_Acceptable_Level, "solved to an acceptable level"},
      {Ipopt::Infeasible_Problem_Detected, "the constraints look infeasible"},
      {Ipopt::Search_Direction_Becomes_Too_Small, "the search direction became too small"},
      {Ipopt::Diverging_Iterates, "the iterates diverged"},
      {Ipopt::User_Requested_Stop, "stopped"},
      {Ipopt::Maximum_Iterations_Exceeded, "the iteration limit was reached"},
      {Ipopt::Restoration_Failed, "the restoration phase failed"},
      {Ipopt::Error_In_Step_Computation, "the step computation failed"},
      {Ipopt::Invalid_Number_Detected, "IPOPT met a non-finite number"},
      {Ipopt::Insufficient_Memory, "out of memory"},
  };
  for (const auto& [code, text] : words)
    if (code == status) return text;
  return "IPOPT failed";
}

std::string status_words(Ipopt::ApplicationReturnStatus status) {
  return status_text(status) + " (IPOPT status " + std::to_string(static_cast<int>(status)) + ")";
}

}  // namespace

void IpoptSolver::set_operator(const SparseMatrix& A, const SparseMatrix& C) {
  if (A.rows() != A.cols() || C.cols() != A.rows())
    throw QpError("ipopt: operator and constraint sizes do not match");
  require_finite(A, "ipopt", "the operator A_S");
  require_finite(C, "ipopt", "the constraint matrix C_S");
  A_ = A;
  C_ = C;
}

void IpoptSolver::set_constraints(const SparseMatrix& C) {
  if (C.cols() != A_.rows()) throw QpError("ipopt: constraint and operator sizes do not match");
  require_finite(C, "ipopt", "the constraint matrix C_S");
  C_ = C;
}

namespace {

// Runs IPOPT on `nlp`; its own exceptions (and running out of memory) become QpError.
Ipopt::ApplicationReturnStatus run_ipopt(const Ipopt::SmartPtr<ContactTnlp>& nlp, double tolerance,
                                         int max_iterations, int& iterations) {
  try {
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    app->Options()->SetIntegerValue("print_level", 0);
    app->Options()->SetStringValue("sb", "yes");
    app->Options()->SetNumericValue("tol", tolerance);
    app->Options()->SetIntegerValue("max_iter", max_iterations);
    app->Options()->SetStringValue("hessian_constant", "yes");
    app->Options()->SetStringValue("jac_c_constant", "yes");
    app->Options()->SetStringValue("jac_d_constant", "yes");
    app->Options()->SetStringValue("mehrotra_algorithm", "yes");   // IPOPT's advice for convex QPs
    app->Options()->SetStringValue("nlp_scaling_method", "none");  // scaled by hand above
    // IPOPT relaxes bounds by 1e-8 by default: the contact rows would be violated by that much.
    app->Options()->SetNumericValue("bound_relax_factor", 0.0);
    if (app->Initialize() != Ipopt::Solve_Succeeded) throw QpError("ipopt: initialisation failed");
    const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
    iterations = Ipopt::IsValid(app->Statistics())
                     ? static_cast<int>(app->Statistics()->IterationCount())
                     : 0;
    return status;
  } catch (const Ipopt::IpoptException& e) {
    throw QpError("ipopt: IPOPT raised " + e.Message());
  } catch (const std::bad_alloc&) {
    throw QpError("ipopt: out of memory");
  }
}

}  // namespace

QpResult IpoptSolver::solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                            const QpResult* warm) {
  if (b.size() != A_.rows() || c.size() != C_.rows())
    throw QpError("ipopt: load or bound has the wrong size");
  require_finite(b, "ipopt", "the load b_S");
  require_finite(c, "ipopt", "the bound c_lb");
  const Scaling scaling = displacement_scale(A_, b, C_, c);
  const Eigen::VectorXd* x0 = warm && warm->x.size() == b.size() ? &warm->x : nullptr;
  Ipopt::SmartPtr<ContactTnlp> nlp = new ContactTnlp(A_, b, C_, c, x0, scaling, progress);

  QpResult result;
  const Ipopt::ApplicationReturnStatus status =
      run_ipopt(nlp, tolerance, max_iterations, result.iterations);
  if (nlp->entered_restoration_)
    throw QpError("ipopt: IPOPT turned to its restoration phase after " +
                  std::to_string(result.iterations) +
                  " iterations (no acceptable step), which IPOPT 3.11 cannot run with the Mehrotra "
                  "predictor-corrector: stopped there; contact.solver = active-set may solve it");
  if (status != Ipopt::Solve_Succeeded && status != Ipopt::Solved_To_Acceptable_Level)
    throw QpError("ipopt: did not solve the contact problem: " + status_words(status));
  result.x = nlp->x_;
  result.alpha = nlp->alpha_.cwiseMax(0.0);
  result.status = status == Ipopt::Solve_Succeeded ? "converged" : "converged to acceptable level";
  const Eigen::VectorXd slack = C_ * result.x - c;
  const double gap_scale = slack_scale(C_, c, result.x);
  result.active.resize(c.size());
  // An interior-point multiplier is never exactly zero: call a row active by its slack.
  for (Eigen::Index i = 0; i < c.size(); ++i) result.active[i] = slack[i] <= 1e-6 * gap_scale;
  result.kkt = solver_kkt_residuals(A_, b, C_, c, result.x, nlp->alpha_);
  if (!(result.kkt.max() <= kkt_tolerance))
    throw QpError("ipopt: KKT residual " + format_kkt(result.kkt) + " above tolerance (" +
                  status_words(status) + ")");
  return result;
}

}  // namespace fsi
