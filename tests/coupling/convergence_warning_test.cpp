// The warning on a stop that may be a chance dip below tol (convergence_warning), on
// increment histories of real runs (bench/compare_freefem.sh, Table 1 rows 11, 12
// and 16 on our meshes).
#include <gtest/gtest.h>

#include "coupling/fixed_point.hpp"

namespace fsi::convergence_warning_test {
namespace {

CouplingResult converged_with(const std::vector<double>& increments) {
  CouplingResult r;
  r.converged = true;
  for (double d : increments) r.history.push_back({.increment = d});
  r.iterations = static_cast<int>(increments.size());
  return r;
}

// Row 11 (ω = 0.2): jumps while χ changes, then a steady fall to tol. No warning.
TEST(ConvergenceWarning, SilentOnASteadyFall) {
  const CouplingResult row11 = converged_with({2.123e-3, 1.445e-3, 1.194e-3, 8.256e-4, 9.536e-4, 7.264e-4, 5.173e-4,
                                               5.416e-4, 5.185e-4, 2.394e-4, 1.862e-4, 1.399e-4, 1.068e-4, 8.243e-5});
  EXPECT_EQ(convergence_warning(row11, 1e-4), "");
  const CouplingResult row12 = converged_with({2.123e-3, 1.471e-3, 8.945e-4, 6.899e-4, 5.486e-4, 5.588e-4,
                                               3.910e-4, 5.028e-4, 2.174e-4, 1.605e-4, 1.195e-4, 7.807e-5});
  EXPECT_EQ(convergence_warning(row12, 1e-4), "");
  std::vector<double> geometric;  // constant ω: a contraction of 0.9 per pass
  for (double d = 2e-3; d >= 1e-4; d *= 0.9) geometric.push_back(d);
  geometric.push_back(geometric.back() * 0.9);
  EXPECT_EQ(convergence_warning(converged_with(geometric), 1e-4), "");
}

// Row 16 (ε = 1e-6): increments wander for 88 passes, then fall 40-fold below tol.
TEST(ConvergenceWarning, NamesAnAbruptFallFromUnsettledIncrements) {
  const CouplingResult row16 = converged_with({2.035e-3, 1.344e-3, 3.109e-3, 4.940e-4, 1.274e-3, 1.153e-3, 6.305e-4,
                                               3.260e-3, 3.871e-4, 1.204e-3, 9.713e-4, 7.121e-4, 3.372e-3, 8.354e-5});
  const std::string w = convergence_warning(row16, 1e-4);
  EXPECT_NE(w.find("chance dip"), std::string::npos) << w;
  EXPECT_NE(w.find("3.37e-03, the last 8.35e-05"), std::string::npos) << w;
  // The same row after a round-off change: the fall took two passes (3.4e-3, 1.0e-4, 8.3e-5).
  const CouplingResult row16b = converged_with({1.404e-3, 1.077e-3, 1.262e-3, 2.034e-3, 1.344e-3, 3.107e-3, 5.005e-4,
                                                1.294e-3, 1.172e-3, 5.186e-4, 3.380e-3, 1.005e-4, 8.334e-5});
  EXPECT_NE(convergence_warning(row16b, 1e-4).find("chance dip"), std::string::npos);
}

TEST(ConvergenceWarning, SilentWhenNotConvergedOrShort) {
  CouplingResult r = converged_with({3e-3, 2e-3, 3e-3, 1e-3, 4e-3, 2e-3, 3e-3, 1e-3, 4e-3, 2e-3, 3e-3, 5e-5});
  EXPECT_NE(convergence_warning(r, 1e-4), "");
  r.converged = false;
  EXPECT_EQ(convergence_warning(r, 1e-4), "");
  EXPECT_EQ(convergence_warning(converged_with({3e-3, 5e-5}), 1e-4), "");
}

// A tolerance coarse for the problem's scale: the §7.2 case scaled by 1e-12 stopped
// in its first pass (increment 6e-19 against tol 1e-4), the increment being the whole
// displacement. The paper's rows stop at ~2% of ‖ũ‖: no warning.
TEST(ConvergenceWarning, NamesAStopWhoseIncrementIsTheDisplacementItself) {
  CouplingResult first_pass = converged_with({6e-19});
  first_pass.final_increment = 6e-19;
  first_pass.final_norm = 6e-19;
  EXPECT_NE(convergence_warning(first_pass, 1e-4).find("coarse for this problem's scale"), std::string::npos);
  CouplingResult paper = converged_with({2e-3, 1e-3, 5e-4, 9.1e-5});
  paper.final_increment = 9.1e-5;
  paper.final_norm = 4.6e-3;
  EXPECT_EQ(convergence_warning(paper, 1e-4), "");
}

}  // namespace
}  // namespace fsi::convergence_warning_test
