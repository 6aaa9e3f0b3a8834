#include "fem/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::quadrature_test {
namespace {

// ∫_T λ1^a λ2^b λ3^c = 2|T| a! b! c! / (a+b+c+2)!  (exact formula to test against).
double exact_monomial(int a, int b, int c) {
  auto f = [](int n) { return std::tgamma(n + 1.0); };
  return 2.0 * f(a) * f(b) * f(c) / f(a + b + c + 2);
}

TEST(Quadrature, GaussLegendreIsExactToDegree2nMinus1) {
  for (int n = 1; n <= 8; ++n) {
    const LineRule g = gauss_legendre(n);
    for (int p = 0; p <= 2 * n - 1; ++p) {
      double s = 0;
      for (int k = 0; k < n; ++k) s += g.w[k] * std::pow(g.x[k], p);
      EXPECT_NEAR(s, 1.0 / (p + 1), 1e-14) << "n=" << n << " p=" << p;
    }
    // and not beyond: x^{2n} is integrated inexactly (error ≥ 3e-10 for n ≤ 8, round-off 1e-16)
    double s = 0;
    for (int k = 0; k < n; ++k) s += g.w[k] * std::pow(g.x[k], 2 * n);
    EXPECT_GT(std::abs(s - 1.0 / (2 * n + 1)), 1e-12) << "n=" << n;
  }
}

TEST(Quadrature, TriangleRuleIntegratesBarycentricMonomials) {
  for (int degree = 0; degree <= 10; ++degree) {
    const TriangleRule rule = triangle_rule(degree);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b) {
        const int c = degree - a - b;
        double s = 0;
        for (std::size_t q = 0; q < rule.w.size(); ++q)
          s += rule.w[q] * std::pow(rule.lambda[q][0], a) * std::pow(rule.lambda[q][1], b) *
               std::pow(rule.lambda[q][2], c);
        EXPECT_NEAR(s, exact_monomial(a, b, c), 1e-14) << a << b << c;
      }
  }
}

}  // namespace
}  // namespace fsi::quadrature_test
