// Richardson extrapolation and the GCI on sequences whose limit and order are known.
#include "study/richardson.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::richardson_test {
namespace {

// φ(h) = φ* + C h^p exactly: the observed order is p, the extrapolation φ*, and the
// GCI bounds the finest level's error |φ₁ − φ*| by its safety factor 1.25. The
// differences carry the values' round-off (ulp(41.4)/ε₂₁ ≈ 1e-9 at the finest level
// here), hence the relative tolerance 1e-6.
TEST(Richardson, RecoversTheOrderAndTheLimitOfAnExactPowerLaw) {
  for (double p : {0.9, 1.0, 2.0, 3.5})
    for (double ratio : {std::sqrt(2.0), 2.0, 3.0}) {
      std::vector<double> values;
      for (int level = 0; level < 5; ++level) values.push_back(41.4 + 7.0 * std::pow(0.5 / std::pow(ratio, level), p));
      const ConvergenceEstimate e = estimate_convergence(values, ratio);
      EXPECT_EQ(e.kind, ConvergenceKind::monotone);
      EXPECT_NEAR(e.observed_order, p, 1e-6 * p) << "p " << p << " r " << ratio;
      EXPECT_NEAR(e.extrapolated, 41.4, 1e-12 * 41.4);
      const double error = std::abs(values.back() - 41.4);
      EXPECT_NEAR(e.gci_abs, 1.25 * error, 1e-6 * error);
      EXPECT_NEAR(e.gci, e.gci_abs / values.back(), 1e-15);
      EXPECT_EQ(e.error_bar, e.gci_abs);
      ASSERT_TRUE(e.asymptotic.has_value());
      EXPECT_TRUE(*e.asymptotic);
      EXPECT_EQ(e.orders.size(), 3u);
    }
}

// Two error terms of opposite signs (as the §7.2 case's structure and fluid errors,
// docs/validation.md): φ = 1 + h − 30 h² turns at h = 1/60, so a sequence across the
// turn is not yet asymptotic (its coarse triple is not even monotone); far below the
// turn the h term rules and the orders agree.
TEST(Richardson, TellsAPreAsymptoticSequence) {
  auto phi = [](double h) { return 1.0 + h - 30 * h * h; };
  std::vector<double> values;
  for (double h : {0.04, 0.02, 0.01, 0.005}) values.push_back(phi(h));
  const ConvergenceEstimate pre = estimate_convergence(values, 2.0);
  ASSERT_TRUE(pre.asymptotic.has_value());
  EXPECT_FALSE(*pre.asymptotic);
  values.clear();
  for (double h : {1e-4, 5e-5, 2.5e-5, 1.25e-5}) values.push_back(phi(h));
  const ConvergenceEstimate fine = estimate_convergence(values, 2.0);
  EXPECT_TRUE(*fine.asymptotic);
  EXPECT_NEAR(fine.observed_order, 1.0, 0.01);
}

TEST(Richardson, NamesOscillationDivergenceAndExactness) {
  const ConvergenceEstimate osc = estimate_convergence({1.0, 1.4, 1.2, 1.3}, 2.0);
  EXPECT_EQ(osc.kind, ConvergenceKind::oscillatory);
  EXPECT_TRUE(std::isnan(osc.extrapolated));
  EXPECT_TRUE(std::isnan(osc.gci));
  EXPECT_FALSE(*osc.asymptotic);
  // No order to extrapolate with: the error bar is 3 × half the finest three's range.
  EXPECT_DOUBLE_EQ(osc.error_bar, 3 * (1.4 - 1.2) / 2);
  const ConvergenceEstimate div = estimate_convergence({1.0, 1.1, 1.3}, 2.0);
  EXPECT_EQ(div.kind, ConvergenceKind::divergent);
  EXPECT_LT(div.observed_order, 0.0);
  EXPECT_TRUE(std::isnan(div.gci));
  EXPECT_TRUE(std::isnan(div.error_bar));  // growing differences bound nothing
  EXPECT_FALSE(div.asymptotic.has_value());  // three levels cannot tell
  const ConvergenceEstimate exact = estimate_convergence({2.0, 2.0, 2.0, 2.0}, 2.0);
  EXPECT_EQ(exact.kind, ConvergenceKind::exact);
  EXPECT_EQ(exact.gci, 0.0);
  EXPECT_EQ(exact.extrapolated, 2.0);
  EXPECT_EQ(exact.error_bar, 0.0);
  EXPECT_EQ(estimate_convergence({1.0, 2.0}, 2.0).kind, ConvergenceKind::too_few);
  // A contact zone's end sits on a vertex: the finest two levels can agree exactly.
  const ConvergenceEstimate settled = estimate_convergence({0.0563, 0.0557, 0.056, 0.056}, 2.0);
  EXPECT_EQ(settled.kind, ConvergenceKind::exact);
  EXPECT_TRUE(std::isnan(settled.observed_order));
  EXPECT_EQ(settled.gci, 0.0);
}

}  // namespace
}  // namespace fsi::richardson_test
