// The penalty's error bar (study/penalty_error.hpp) on a model φ(ε) = φ₀ + C ε^q.
#include "study/penalty_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::penalty_error_test {
namespace {

double model(double eps, double q) {
  return 18.8 - 250 * std::pow(eps, q);
}

// With q = 1/2, the assumed order, the bar is Fs = 1.5 times the true error, at any r;
// with q = 0.39 (measured on the no-contact case) it still covers at r = 2 and √2; at
// q = 1/4 (the energy-norm bound) it does not, and says nothing it cannot.
TEST(PenaltyError, IsASafetyFactorTimesTheErrorOfAnEpsToTheHalf) {
  for (const double r : {2.0, std::sqrt(2.0)}) {
    const double eps = 1e-4;
    const PenaltyError e = penalty_error(eps, model(eps, 0.5), model(eps * r * r, 0.5), r);
    EXPECT_DOUBLE_EQ(e.eps_check, eps * r * r);
    EXPECT_NEAR(e.error_bar, 1.5 * std::abs(model(eps, 0.5) - model(0, 0.5)), 1e-12);
    const PenaltyError slow = penalty_error(eps, model(eps, 0.39), model(eps * r * r, 0.39), r);
    EXPECT_GT(slow.error_bar, std::abs(model(eps, 0.39) - model(0, 0.39)));
    const PenaltyError slower = penalty_error(eps, model(eps, 0.25), model(eps * r * r, 0.25), r);
    EXPECT_LT(slower.error_bar, std::abs(model(eps, 0.25) - model(0, 0.25)));
  }
  EXPECT_TRUE(std::isnan(penalty_error(1e-4, 1.0, NAN, 2).error_bar));
  EXPECT_EQ(penalty_error(1e-4, 1.0, 1.0, 2).error_bar, 0.0);
}

}  // namespace
}  // namespace fsi::penalty_error_test
