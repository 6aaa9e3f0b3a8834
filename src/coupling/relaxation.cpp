#include "coupling/relaxation.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

namespace fsi {
namespace {

class ConstantRelaxation final : public Relaxation {
 public:
  explicit ConstantRelaxation(double omega) : omega_(omega) {}
  Eigen::VectorXd next(const Eigen::VectorXd& u, const Eigen::VectorXd& H_u, const Projection&) override {
    return u + omega_ * (H_u - u);  // convex combination of feasible fields: feasible
  }
  double omega() const override { return omega_; }
  std::string name() const override { return "constant"; }

 private:
  double omega_;
};

class AitkenRelaxation final : public Relaxation {
 public:
  AitkenRelaxation(const RelaxationOptions& o, const Eigen::SparseMatrix<double>& M)
      : omega_(o.omega0), omega0_(o.omega0), omega_min_(o.omega_min), M_(M) {}
  void end_window() override {
    omega_ = omega0_;
    previous_r_.resize(0);
  }
  Eigen::VectorXd next(const Eigen::VectorXd& u, const Eigen::VectorXd& H_u, const Projection&) override {
    const Eigen::VectorXd r = H_u - u;
    if (previous_r_.size() == r.size()) {
      const Eigen::VectorXd dr = r - previous_r_;
      const double denominator = dr.dot(M_ * dr);
      // ‖Δr‖ ≈ 0 means the residual stopped changing: keep ω.
      if (denominator > 1e-30 * std::max(r.dot(M_ * r), 1e-300)) {
        const double w = -omega_ * previous_r_.dot(M_ * dr) / denominator;
        omega_ = std::isfinite(w) ? std::clamp(w, omega_min_, 1.0) : omega_;
      }
    }
    previous_r_ = r;
    return u + omega_ * r;
  }
  double omega() const override { return omega_; }
  std::string name() const override { return "aitken"; }

 private:
  double omega_, omega0_, omega_min_;
  Eigen::SparseMatrix<double> M_;
  Eigen::VectorXd previous_r_;
};

// x ↦ Lᵀ P x with P M Pᵀ = L Lᵀ (sparse Cholesky): ‖Lᵀ P x‖ = ‖x‖_M, so a Euclidean
// least-squares problem on the mapped vectors is the one in the L²(Ω_S0) norm.
class MassNorm {
 public:
  explicit MassNorm(const Eigen::SparseMatrix<double>& M) : cholesky_(M) {
    if (cholesky_.info() != Eigen::Success)
      throw std::invalid_argument("iqn-ils: the mass matrix is not positive definite");
  }
  Eigen::VectorXd map(const Eigen::VectorXd& x) const {
    return cholesky_.matrixU() * (cholesky_.permutationP() * x);
  }

 private:
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> cholesky_;
};

class IqnIlsRelaxation final : public Relaxation {
 public:
  IqnIlsRelaxation(const RelaxationOptions& o, const Eigen::SparseMatrix<double>& M)
      : options_(o), norm_(M) {}

  Eigen::VectorXd next(const Eigen::VectorXd& u, const Eigen::VectorXd& H_u, const Projection& project) override {
    const Eigen::VectorXd r = H_u - u;
    if (previous_r_.size() == r.size()) {
      V_.push_front(r - previous_r_);
      W_.push_front(H_u - previous_H_);
      window_of_.push_front(window_);
      if (static_cast<int>(V_.size()) > options_.max_columns) {
        V_.pop_back();
        W_.pop_back();
        window_of_.pop_back();
      }
    }
    previous_r_ = r;
    previous_H_ = H_u;
    if (V_.empty()) {
      omega_ = options_.omega0;
      return u + options_.omega0 * r;  // first step: constant relaxation
    }
    omega_ = std::numeric_limits<double>::quiet_NaN();
    // The coefficients first: least_squares drops the filtered columns from V and W,
    // and W must then be formed from what is left (as one expression, W_matrix() was
    // evaluated first, a column too wide for α: found by fuzz_cli).
    const Eigen::VectorXd alpha = least_squares(r);
    const Eigen::MatrixXd W = W_matrix();
    if (W.cols() != alpha.size()) throw std::logic_error("iqn-ils: W and the coefficients disagree in size");
    Eigen::VectorXd z = H_u + W * alpha;
    if (project) {
      const Eigen::VectorXd feasible = project(z);
      if ((feasible - z).norm() > 0) ++projections_;
      z = feasible;
    }
    return z;
  }
  double omega() const override { return omega_; }
  std::string name() const override { return "iqn-ils"; }
  State saved() const override {
    State s = Relaxation::saved();
    const Eigen::Index n = V_.empty() ? 0 : V_[0].size(), k = static_cast<Eigen::Index>(V_.size());
    Eigen::VectorXd V(n * k), W(n * k), windows(k);
    for (Eigen::Index j = 0; j < k; ++j) {
      V.segment(j * n, n) = V_[static_cast<std::size_t>(j)], W.segment(j * n, n) = W_[static_cast<std::size_t>(j)];
      windows[j] = window_of_[static_cast<std::size_t>(j)];
    }
    s["V"] = V, s["W"] = W, s["column_windows"] = windows, s["window"] = Eigen::VectorXd::Constant(1, window_);
    return s;
  }
  void restore(const State& s) override {
    Relaxation::restore(s);
    const Eigen::VectorXd &V = s.at("V"), &W = s.at("W"), &windows = s.at("column_windows");
    const Eigen::Index k = windows.size(), n = k ? V.size() / k : 0;
    if (V.size() != n * k || W.size() != n * k) throw std::invalid_argument("iqn-ils: restored columns of unequal sizes");
    V_.clear(), W_.clear(), window_of_.clear();
    for (Eigen::Index j = 0; j < k; ++j) {
      V_.push_back(V.segment(j * n, n)), W_.push_back(W.segment(j * n, n));
      window_of_.push_back(static_cast<int>(windows[j]));
    }
    window_ = static_cast<int>(s.at("window")[0]);
    previous_r_.resize(0), previous_H_.resize(0);
  }
  // Columns are tagged with their window; those older than reused_windows go.
  void end_window() override {
    previous_r_.resize(0);
    previous_H_.resize(0);
    ++window_;
    while (!window_of_.empty() && window_ - window_of_.back() > options_.reused_windows) {
      V_.pop_back(), W_.pop_back(), window_of_.pop_back();
    }
  }

 private:
  // α = argmin ‖V α + r‖_M (the L²(Ω_S0) norm, M the consistent mass), by modified
  // Gram–Schmidt on the mapped columns newest first; a column whose new part is below
  // `filter` of its norm is nearly dependent on newer ones and is dropped for good
  // (the QR filter).
  Eigen::VectorXd least_squares(const Eigen::VectorXd& r) {
    std::vector<Eigen::VectorXd> Q;
    std::vector<std::size_t> kept;
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(V_.size()), static_cast<Eigen::Index>(V_.size()));
    for (std::size_t j = 0; j < V_.size(); ++j) {
      Eigen::VectorXd q = norm_.map(V_[j]);
      const double norm0 = q.norm();
      Eigen::VectorXd coeffs(static_cast<Eigen::Index>(Q.size()));
      for (std::size_t i = 0; i < Q.size(); ++i) {
        coeffs[static_cast<Eigen::Index>(i)] = Q[i].dot(q);
        q -= coeffs[static_cast<Eigen::Index>(i)] * Q[i];
      }
      const double rjj = q.norm();
      if (!(rjj > options_.filter * norm0)) continue;
      const Eigen::Index col = static_cast<Eigen::Index>(Q.size());
      R.block(0, col, col, 1) = coeffs;
      R(col, col) = rjj;
      Q.push_back(q / rjj);
      kept.push_back(j);
    }
    // Drop the filtered columns from the history.
    std::deque<Eigen::VectorXd> V, W;
    std::deque<int> windows;
    for (std::size_t j : kept) V.push_back(V_[j]), W.push_back(W_[j]), windows.push_back(window_of_[j]);
    V_.swap(V);
    W_.swap(W);
    window_of_.swap(windows);
    const Eigen::Index n = static_cast<Eigen::Index>(Q.size());
    Eigen::VectorXd rhs(n);
    const Eigen::VectorXd wr = norm_.map(r);
    for (Eigen::Index i = 0; i < n; ++i) rhs[i] = -Q[static_cast<std::size_t>(i)].dot(wr);
    return R.topLeftCorner(n, n).triangularView<Eigen::Upper>().solve(rhs);
  }
  Eigen::MatrixXd W_matrix() const {
    Eigen::MatrixXd W(W_.empty() ? 0 : W_[0].size(), static_cast<Eigen::Index>(W_.size()));
    for (std::size_t j = 0; j < W_.size(); ++j) W.col(static_cast<Eigen::Index>(j)) = W_[j];
    return W;
  }

  RelaxationOptions options_;
  MassNorm norm_;
  std::deque<Eigen::VectorXd> V_, W_;
  std::deque<int> window_of_;  // the time window each column was formed in
  int window_ = 0;
  Eigen::VectorXd previous_r_, previous_H_;
  double omega_ = 0;
};

}  // namespace

std::unique_ptr<Relaxation> make_relaxation(const std::string& scheme, const RelaxationOptions& options,
                                            const Eigen::SparseMatrix<double>& M) {
  if (scheme == "constant") return std::make_unique<ConstantRelaxation>(options.omega0);
  if (scheme == "aitken") return std::make_unique<AitkenRelaxation>(options, M);
  if (scheme == "iqn-ils") return std::make_unique<IqnIlsRelaxation>(options, M);
  throw std::invalid_argument("unknown relaxation scheme '" + scheme + "'");
}

}  // namespace fsi
