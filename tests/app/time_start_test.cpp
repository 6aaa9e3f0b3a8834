// time.start_from = "steady" (SPEC §12): a time run from the steady solution of its own
// case at t = 0. The steady state is in equilibrium, so the structure alone and the
// fluid alone stay in it while their data stay constant: the test that the start is the
// steady problem's solution and that the time schemes share its fixed point. The
// coupled run's row 0 is the steady coupled run's answer.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/history.hpp"

namespace fsi::time_start_test {
namespace {

namespace fs = std::filesystem;

const std::string kCases = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/";

// Column `name` of history.csv, every row.
std::vector<double> column(const fs::path& file, const std::string& name) { return testing::read_history(file).values(name); }

// Turek–Hron CSM3's flag from its static deflection under gravity (CSM1's problem):
// it stays there, to round-off, through 10 steps of Newmark.
TEST(TimeStart, TheStructureStaysInItsSteadyState) {
  const fs::path dir = testing::scratch_dir("start-structure");
  const testing::CliRun r = testing::run_cli(
      "run " + kCases + "turek-hron-csm3.toml' --set structure.h=0.004 --set time.start_from=steady "
      "--set time.t_end=0.05 -q --out res --set output.png=false --set output.vtu=false",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> u = column(dir / "res/history.csv", "max_u"), k = column(dir / "res/history.csv", "kinetic");
  ASSERT_EQ(u.size(), 11u);
  EXPECT_GT(u[0], 0.06);  // CSM1's tip deflection is 66 mm
  for (std::size_t i = 1; i < u.size(); ++i) {
    EXPECT_NEAR(u[i], u[0], 1e-9 * u[0]) << "step " << i;
    EXPECT_LT(k[i], 1e-15) << "step " << i;
  }
}

// DFG 2D-2 from its steady flow: before the instability grows, every BDF2 step keeps it
// (Newton has nothing to do) and the drag stays the steady drag.
TEST(TimeStart, TheFluidStaysInItsSteadyFlow) {
  const fs::path dir = testing::scratch_dir("start-fluid");
  const testing::CliRun r = testing::run_cli(
      "run " + kCases + "dfg-2d2.toml' --set fluid.h_near=0.02 --set fluid.mesher=lattice --set time.start_from=steady "
      "--set time.t_end=0.05 -q --out res --set output.png=false --set output.vtu=false",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> drag = column(dir / "res/history.csv", "obstacle_1_force_x");
  ASSERT_EQ(drag.size(), 5u);
  for (double d : drag) EXPECT_NEAR(d, drag[0], 1e-10 * drag[0]);
  const std::vector<double> newton = column(dir / "res/history.csv", "newton_steps");
  for (double n : newton) EXPECT_EQ(n, 0);
}

// The coupled run's initial state is the steady run's solution: row 0's max |u| is the
// steady run's max_displacement.
TEST(TimeStart, TheCoupledRunStartsFromTheSteadyAnswer) {
  const fs::path dir = testing::scratch_dir("start-coupled");
  const std::string coarse = " --set fluid.h=0.03 --set structure.h=0.03 -q --set output.png=false --set output.vtu=false";
  ASSERT_EQ(testing::run_cli("run " + kCases + "paper-7.2.toml'" + coarse + " --out steady", dir).status, 0);
  const testing::CliRun r = testing::run_cli(
      "run " + kCases + "paper-7.2.toml'" + coarse +
          " --set time.dt=0.01 --set time.t_end=0.01 --set time.start_from=steady --set structure.rho=1100 "
          "--set fluid.rho=100 --out time",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto steady = nlohmann::json::parse(testing::slurp(dir / "steady/summary.json"));
  const std::vector<double> u = column(dir / "time/history.csv", "max_u");
  ASSERT_EQ(u.size(), 2u);
  EXPECT_NEAR(u[0], steady["max_displacement"].get<double>(), 1e-12);
}

}  // namespace
}  // namespace fsi::time_start_test
