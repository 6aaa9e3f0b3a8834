#include <algorithm>
#include <cmath>
#include <cstdio>

#include "qp/qp_problem.hpp"

namespace fsi {

double KktResiduals::max() const {
  // std::max drops NaN (every comparison with it is false): a NaN residual must fail.
  double m = 0;
  for (double r : {stationarity, feasibility, complementarity, dual_feasibility}) {
    if (std::isnan(r)) return r;
    m = std::max(m, r);
  }
  return m;
}

int QpResult::active_count() const {
  return static_cast<int>(std::count(active.begin(), active.end(), true));
}

std::string format_kkt(const KktResiduals& r) {
  char text[200];
  std::snprintf(text, sizeof text,
                "stationarity %.2e, feasibility %.2e, complementarity %.2e, dual feasibility %.2e",
                r.stationarity, r.feasibility, r.complementarity, r.dual_feasibility);
  return text;
}

namespace {

// ‖M‖∞, the largest absolute row sum.
double norm_inf(const SparseMatrix& M) {
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(M.rows());
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(M, j); it; ++it) row_sums[it.row()] += std::abs(it.value());
  return row_sums.size() ? row_sums.maxCoeff() : 0.0;
}

// max_j |M_ij| for each row i.
Eigen::VectorXd row_max(const SparseMatrix& M) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(M.rows());
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(M, j); it; ++it)
      out[it.row()] = std::max(out[it.row()], std::abs(it.value()));
  return out;
}

double inf_norm(const Eigen::VectorXd& v) {
  return v.size() ? v.lpNorm<Eigen::Infinity>() : 0.0;
}

constexpr double tiny = 1e-300;

// The residuals of (x, alpha), except that dual feasibility is measured on `signed_alpha`
// (the same vector or the solver's multipliers before clamping).
KktResiduals residuals(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
                       const Eigen::VectorXd& c, const Eigen::VectorXd& x,
                       const Eigen::VectorXd& alpha, const Eigen::VectorXd& signed_alpha) {
  const Eigen::VectorXd Ax = A * x, Cx = C * x, Ct_alpha = C.transpose() * alpha;
  KktResiduals r;
  // Normwise backward error: a backward-stable solve leaves ‖Ax − b − Cᵀα‖ of order
  // u·‖A‖‖x‖, which exceeds u·‖Ax‖ by up to cond(A) (ν → 0.5: λ/μ = 5e6 gave 1e-7
  // relative to ‖Ax‖ for an exact solve). A wrong x still shows as O(1).
  const double force_scale =
      std::max(norm_inf(A) * inf_norm(x) + inf_norm(b) + inf_norm(Ct_alpha), tiny);
  r.stationarity = inf_norm(Ax - b - Ct_alpha) / force_scale;
  if (c.size() == 0) return r;
  const double gap_scale = slack_scale(C, c, x);
  r.feasibility = (c - Cx).cwiseMax(0.0).maxCoeff() / gap_scale;
  // Each factor normalised before the product, which would overflow for α ~ 1e294.
  const double alpha_scale = std::max(inf_norm(alpha), tiny);
  r.complementarity = inf_norm((alpha / alpha_scale).cwiseProduct((Cx - c) / gap_scale));
  // A negative α_i pulls with the force α_i C_iᵀ: measured as the stationarity is.
  // Relative to ‖α‖∞ instead, an interior-point method's ±1e-20 on rows without
  // contact (all α ≈ 0) would count as 100%.
  r.dual_feasibility =
      (-signed_alpha).cwiseMax(0.0).cwiseProduct(row_max(C)).maxCoeff() / force_scale + 0.0;
  return r;
}

}  // namespace

double slack_scale(const SparseMatrix& C, const Eigen::VectorXd& c, const Eigen::VectorXd& x) {
  const double c_norm = c.size() ? c.lpNorm<Eigen::Infinity>() : 0.0;
  const double Cx_norm = norm_inf(C) * (x.size() ? x.lpNorm<Eigen::Infinity>() : 0.0);
  return std::max({c_norm, Cx_norm, 1e-300});
}

KktResiduals kkt_residuals(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
                           const Eigen::VectorXd& c, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& alpha) {
  return residuals(A, b, C, c, x, alpha, alpha);
}

KktResiduals solver_kkt_residuals(const SparseMatrix& A, const Eigen::VectorXd& b,
                                  const SparseMatrix& C, const Eigen::VectorXd& c,
                                  const Eigen::VectorXd& x, const Eigen::VectorXd& raw_alpha) {
  return residuals(A, b, C, c, x, raw_alpha.cwiseMax(0.0), raw_alpha);
}

void require_finite(const SparseMatrix& M, const std::string& who, const std::string& what) {
  // The stored entries, by column: a matrix not yet compressed has gaps in its value
  // array, so coeffs() would not be its entries (Eigen asserts so; the instrumented
  // build caught it). An implicit zero is finite.
  for (int k = 0; k < M.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M, k); it; ++it)
      if (!std::isfinite(it.value())) throw QpError(who + ": " + what + " has a non-finite entry");
}

void require_finite(const Eigen::VectorXd& v, const std::string& who, const std::string& what) {
  if (!v.allFinite()) throw QpError(who + ": " + what + " has a non-finite entry");
}

}  // namespace fsi
