#include "fem/quadrature.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fsi {

LineRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be positive");
  LineRule rule;
  rule.x.resize(n);
  rule.w.resize(n);
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from the Chebyshev-like initial guess; converges in a few steps.
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.x[i] = 0.5 * (1.0 - t);
    rule.w[i] = 1.0 / ((1.0 - t * t) * dp * dp);  // 2/((1−t²)P'²) scaled by 1/2
  }
  return rule;
}

TriangleRule triangle_rule(int degree) {
  // Duffy map (s,t) ∈ [0,1]² → (x,y) = (s, t(1−s)) with Jacobian (1−s): a degree-d
  // polynomial becomes degree d+1 in s and d in t, so n = ⌈(d+2)/2⌉ points suffice.
  const int n = std::max(1, (degree + 3) / 2);
  const LineRule g = gauss_legendre(n);
  TriangleRule rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = g.x[i], y = g.x[j] * (1.0 - g.x[i]);
      rule.lambda.emplace_back(1.0 - x - y, x, y);
      rule.w.push_back(2.0 * g.w[i] * g.w[j] * (1.0 - g.x[i]));  // reference area 1/2
    }
  return rule;
}

}  // namespace fsi
