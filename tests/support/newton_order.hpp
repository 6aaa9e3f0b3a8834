// Newton's quadratic convergence read off a residual history (SPEC §11's verification).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fsi::testing {

// The observed order p = log(r_{k+1}/r_k) / log(r_k/r_{k-1}) (free of the residual's
// scale) ≥ 1.8 on the last triple of residuals above 1e-14, the backward error's
// round-off floor being ~1e-16.
inline void expect_quadratic(const std::vector<double>& r) {
  int last = -1;
  for (std::size_t k = 2; k < r.size(); ++k)
    if (r[k] > 1e-14) last = static_cast<int>(k);
  ASSERT_GE(last, 2) << "too few steps above round-off to see an order";
  const double order = std::log(r[last] / r[last - 1]) / std::log(r[last - 1] / r[last - 2]);
  EXPECT_GE(order, 1.8) << r[last - 2] << " -> " << r[last - 1] << " -> " << r[last];
}

}  // namespace fsi::testing
