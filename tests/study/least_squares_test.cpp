// The least-squares estimate (study/least_squares.hpp) on sequences with known limits:
// exact power laws give back their limit and order; scattered ones a limit within the
// scatter and an uncertainty that covers the true error.
#include <gtest/gtest.h>

#include <cmath>

#include "study/least_squares.hpp"

namespace fsi::least_squares_test {
namespace {

std::vector<double> sizes(int n, double r) {
  std::vector<double> h;
  for (int i = 0; i < n; ++i) h.push_back(0.002 / std::pow(r, i));
  return h;
}

TEST(LeastSquares, RecoversAnExactPowerLaw) {
  for (double p : {1.0, 1.5, 2.0}) {
    const std::vector<double> h = sizes(5, std::sqrt(2.0));
    std::vector<double> v;
    for (double x : h) v.push_back(37.3 - 2e3 * std::pow(x, p) * std::pow(0.002, -p) * 0.01);
    const LeastSquaresEstimate e = least_squares_estimate(h, v);
    EXPECT_NEAR(e.order, p, 1e-4) << p;
    EXPECT_NEAR(e.limit, 37.3, 1e-6) << p;
    EXPECT_LT(e.sigma, 1e-9) << p;
    EXPECT_EQ(e.safety, 1.25) << p;
    // U = 1.25 |φ₁ − φ₀| when the fit is exact.
    EXPECT_NEAR(e.uncertainty, 1.25 * std::abs(v.back() - 37.3), 1e-6) << p;
  }
}

// A first-order sequence with ±3 % of its error as scatter (the contact zone's jumps):
// extrapolating amplifies the scatter (measured: the limit is off by a quarter of the
// finest level's error), and the uncertainty covers the finest level's true error.
TEST(LeastSquares, BoundsTheErrorOfAScatteredSequence) {
  const std::vector<double> h = sizes(6, std::sqrt(2.0));
  const double noise[] = {0.03, -0.03, 0.02, -0.03, 0.03, -0.02};
  std::vector<double> v;
  for (std::size_t i = 0; i < h.size(); ++i) v.push_back(10.0 + 50 * h[i] * (1 + noise[i]));
  const LeastSquaresEstimate e = least_squares_estimate(h, v);
  EXPECT_NEAR(e.limit, 10.0, 0.5 * (v.back() - 10.0));
  EXPECT_GT(e.uncertainty, std::abs(v.back() - 10.0));
  EXPECT_LT(e.uncertainty, 5 * std::abs(v.back() - 10.0));
  EXPECT_GT(e.order, 0.7);
  EXPECT_LT(e.order, 1.3);
}

// No convergence shown (values that wander): p clamps at 0.5, Fs = 3, and U is at
// least the wander.
TEST(LeastSquares, ClampsTheOrderOfAWanderingSequence) {
  const std::vector<double> h = sizes(4, 2.0);
  const std::vector<double> v = {1.0, 1.4, 1.2, 1.3};
  const LeastSquaresEstimate e = least_squares_estimate(h, v);
  EXPECT_EQ(e.safety, 3.0);
  EXPECT_TRUE(e.order_at_bound);
  EXPECT_GE(e.uncertainty, 1.25 * (1.4 - 1.0));  // at least 1.25 × the data's range
  EXPECT_TRUE(std::isnan(least_squares_estimate(sizes(3, 2.0), {1.0, 1.1, 1.15}).limit));  // too few levels
}

}  // namespace
}  // namespace fsi::least_squares_test
