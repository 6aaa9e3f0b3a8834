#include "qp/ipopt_solver.hpp"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <cstdio>

namespace fsi {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// min ½ yᵀ Â y − b̂ᵀ y  s.t.  Ĉ y ≥ ĉ, the problem scaled so that y, the objective
// and the constraints are O(1): x = ℓ y, objective / (ℓ² ‖A‖), constraints / (ℓ ‖C‖).
// IPOPT's absolute tolerances (constr_viol_tol, dual_inf_tol) assume such scaling;
// the raw contact QP has displacements of 1e-3 m and constraint values of 1e-6 m².
class ContactTnlp final : public Ipopt::TNLP {
 public:
  ContactTnlp(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
              const Eigen::VectorXd& c, const Eigen::VectorXd* x0, double length,
              std::function<void(const std::string&)> progress)
      : b_(b), c_(c), x0_(x0), length_(length), progress_(std::move(progress)) {
    a_scale_ = 1.0 / (length * length * std::max(A.coeffs().cwiseAbs().maxCoeff(), 1e-300));
    c_scale_ = C.nonZeros() ? 1.0 / (length * C.coeffs().cwiseAbs().maxCoeff()) : 1.0;
    A_ = (A * (length * length * a_scale_)).triangularView<Eigen::Lower>();
    A_full_ = A * (length * length * a_scale_);
    C_ = C * (length * c_scale_);
    A_.makeCompressed();
    C_.makeCompressed();
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
    for (Index i = 0; i < m; ++i) g_l[i] = c_[i] * c_scale_, g_u[i] = 2e19;
    return true;
  }
  bool get_starting_point(Index n, bool init_x, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    if (init_x)
      for (Index i = 0; i < n; ++i) x[i] = x0_ ? (*x0_)[i] / length_ : 0.0;
    return true;
  }
  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    const Eigen::Map<const Eigen::VectorXd> y(x, n);
    f = 0.5 * y.dot(A_full_ * y) - length_ * a_scale_ * b_.dot(y);
    return true;
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    const Eigen::Map<const Eigen::VectorXd> y(x, n);
    Eigen::Map<Eigen::VectorXd>(g, n) = A_full_ * y - (length_ * a_scale_) * b_;
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
  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj, Number inf_pr,
                             Number inf_du, Number mu, Number, Number, Number, Number, Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
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
    x_ = Eigen::Map<const Eigen::VectorXd>(x, n) * length_;
    // IPOPT's Lagrangian is f + λᵀg: λ ≤ 0 on a lower bound, so α = −λ, unscaled.
    alpha_ = -Eigen::Map<const Eigen::VectorXd>(lambda, m) * (c_scale_ / a_scale_);
  }

  Ipopt::SolverReturn status_ = Ipopt::INTERNAL_ERROR;
  Eigen::VectorXd x_, alpha_;  // alpha_: IPOPT's multipliers, unscaled, not clamped

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

  SparseMatrix A_, A_full_, C_;
  Eigen::VectorXd b_, c_;
  const Eigen::VectorXd* x0_;
  double length_, a_scale_ = 1, c_scale_ = 1;
  std::function<void(const std::string&)> progress_;
};

// A length scale for the displacements: the gap the constraints must close, or, if
// there is none, the displacement a single node sees under its own load.
double displacement_scale(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
                          const Eigen::VectorXd& c) {
  double scale = 0;
  if (C.nonZeros() && c.size()) {
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(C.rows());
    for (Eigen::Index j = 0; j < C.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(C, j); it; ++it) row_sums[it.row()] += std::abs(it.value());
    for (Eigen::Index i = 0; i < C.rows(); ++i)
      if (row_sums[i] > 0) scale = std::max(scale, std::abs(c[i]) / row_sums[i]);
  }
  if (scale == 0 && b.size()) scale = b.lpNorm<Eigen::Infinity>() / A.diagonal().maxCoeff();
  return scale > 0 ? scale : 1.0;
}

}  // namespace

void IpoptSolver::set_operator(const SparseMatrix& A, const SparseMatrix& C) {
  if (A.rows() != A.cols() || C.cols() != A.rows())
    throw QpError("ipopt: operator and constraint sizes do not match");
  A_ = A;
  C_ = C;
}

QpResult IpoptSolver::solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                            const QpResult* warm) {
  if (b.size() != A_.rows() || c.size() != C_.rows())
    throw QpError("ipopt: load or bound has the wrong size");
  const double length = displacement_scale(A_, b, C_, c);
  const Eigen::VectorXd* x0 = warm && warm->x.size() == b.size() ? &warm->x : nullptr;
  Ipopt::SmartPtr<ContactTnlp> nlp = new ContactTnlp(A_, b, C_, c, x0, length, progress);

  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetNumericValue("tol", tolerance);
  app->Options()->SetIntegerValue("max_iter", max_iterations);
  app->Options()->SetStringValue("hessian_constant", "yes");
  app->Options()->SetStringValue("jac_c_constant", "yes");
  app->Options()->SetStringValue("jac_d_constant", "yes");
  app->Options()->SetStringValue("mehrotra_algorithm", "yes");  // IPOPT's advice for convex QPs
  app->Options()->SetStringValue("nlp_scaling_method", "none");  // scaled by hand above
  // IPOPT relaxes bounds by 1e-8 by default: the contact rows would be violated by that much.
  app->Options()->SetNumericValue("bound_relax_factor", 0.0);
  if (app->Initialize() != Ipopt::Solve_Succeeded) throw QpError("ipopt: initialisation failed");
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);

  QpResult result;
  result.iterations = Ipopt::IsValid(app->Statistics()) ? static_cast<int>(app->Statistics()->IterationCount()) : 0;
  if (status != Ipopt::Solve_Succeeded && status != Ipopt::Solved_To_Acceptable_Level)
    throw QpError("ipopt: did not solve the contact problem (IPOPT status " +
                  std::to_string(static_cast<int>(status)) + ")");
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
    throw QpError("ipopt: KKT residual " + format_kkt(result.kkt) +
                  " above tolerance (IPOPT status " + std::to_string(static_cast<int>(status)) + ")");
  return result;
}

}  // namespace fsi
