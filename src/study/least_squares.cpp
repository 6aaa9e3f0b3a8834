#include "study/least_squares.hpp"

#include <algorithm>
#include <cstddef>

namespace fsi {
namespace {

constexpr double kMinOrder = 0.5, kMaxOrder = 2.05;

struct Fit {
  double phi0 = NAN, alpha = NAN, residual = INFINITY;  // residual: Σ (φ_i − fit_i)²
};

// For a fixed p the fit is linear in (φ₀, α): the 2×2 normal equations.
Fit fit_with_order(const std::vector<double>& h, const std::vector<double>& v, double p) {
  const double n = static_cast<double>(h.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::pow(h[i], p);
    sx += x, sy += v[i], sxx += x * x, sxy += x * v[i];
  }
  Fit f;
  const double det = n * sxx - sx * sx;
  if (!(std::abs(det) > 0)) return f;
  f.alpha = (n * sxy - sx * sy) / det;
  f.phi0 = (sy - f.alpha * sx) / n;
  f.residual = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double r = v[i] - (f.phi0 + f.alpha * std::pow(h[i], p));
    f.residual += r * r;
  }
  return f;
}

// The p minimising the residual over [lo, hi]: a scan (the residual can have several
// local minima with four to six points), then golden-section refinement.
double best_order(const std::vector<double>& h, const std::vector<double>& v, double lo, double hi) {
  double best = lo, best_residual = INFINITY;
  const int steps = 200;
  for (int k = 0; k <= steps; ++k) {
    const double p = lo + (hi - lo) * k / steps;
    const double r = fit_with_order(h, v, p).residual;
    if (r < best_residual) best_residual = r, best = p;
  }
  double a = std::max(lo, best - (hi - lo) / steps), b = std::min(hi, best + (hi - lo) / steps);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 60; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (fit_with_order(h, v, c).residual < fit_with_order(h, v, d).residual) b = d;
    else a = c;
  }
  return (a + b) / 2;
}

}  // namespace

LeastSquaresEstimate least_squares_estimate(const std::vector<double>& h, const std::vector<double>& values) {
  LeastSquaresEstimate e;
  const std::size_t n = values.size();
  if (n < 4 || h.size() != n) return e;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i]) || !(h[i] > 0)) return e;
  // Where the unconstrained best order lies beyond the range, the bound is used.
  const double free_p = best_order(h, values, 0.05, 8.0);
  e.order = std::clamp(best_order(h, values, kMinOrder, kMaxOrder), kMinOrder, kMaxOrder);
  e.order_at_bound = free_p < kMinOrder || free_p > kMaxOrder;
  const Fit f = fit_with_order(h, values, e.order);
  e.limit = f.phi0, e.coefficient = f.alpha;
  e.sigma = std::sqrt(f.residual / static_cast<double>(n - 3));  // three parameters fitted
  const std::size_t finest = static_cast<std::size_t>(std::min_element(h.begin(), h.end()) - h.begin());
  const double phi1 = values[finest];
  const double spread = (*std::max_element(values.begin(), values.end()) - *std::min_element(values.begin(), values.end())) /
                        static_cast<double>(n - 1);
  e.safety = (e.order >= 0.95 && e.order <= kMaxOrder && !e.order_at_bound && e.sigma < spread) ? 1.25 : 3.0;
  e.uncertainty = e.safety * std::abs(phi1 - e.limit) + e.sigma +
                  std::abs(phi1 - (e.limit + e.coefficient * std::pow(h[finest], e.order)));
  if (e.order_at_bound) e.uncertainty = std::max(e.uncertainty, 1.25 * spread * static_cast<double>(n - 1));
  return e;
}

}  // namespace fsi
