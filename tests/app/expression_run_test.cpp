// SPEC §10's expressions end to end through `fsicontact run` (coarse §7.2 case): the
// numbers as strings, and expressions equal to them everywhere, give the numbers'
// summary bit for bit; an expression that varies in space gives another finite
// answer; one that meets NaN fails the run (exit 1, summary "failed") naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::expression_run_test {
namespace {

namespace fs = std::filesystem;
const std::string kCoarse = "--set fluid.h=0.02 --set structure.h=0.03 --set output.png=false --set output.vtu=false";

nlohmann::json run_summary(const fs::path& dir, const std::string& out, const std::string& args, int status = 0) {
  const testing::CliRun r = testing::run_cli("run -q " + kCoarse + " --out " + out + " " + args, dir);
  EXPECT_EQ(r.status, status) << args << "\n" << r.err;
  return nlohmann::json::parse(testing::slurp(dir / out / "summary.json"));
}

// The summary without what a run does not repeat (times) or what differs by design
// (the parameters as given, the output directory).
nlohmann::json results(nlohmann::json j) {
  j.erase("parameters");
  j.erase("timing_s");
  for (auto it = j["fluid"].begin(); it != j["fluid"].end();)
    it = it.key().size() > 2 && it.key().ends_with("_s") ? j["fluid"].erase(it) : std::next(it);
  return j;
}

TEST(ExpressionRun, NumbersGivenAsStringsOrAsConstantExpressionsRunBitForBit) {
  const fs::path dir = testing::scratch_dir("expression-same");
  const auto numbers = run_summary(dir, "numbers", "");
  // Constants: the number path itself.
  const auto strings = run_summary(dir, "strings", "--set 'fluid.Vmax=\"8.0\"' --set 'fluid.f=[\"0\", \"-981\"]' "
                                                    "--set 'structure.f=[0, \"-10791.0\"]'");
  // Varying texts whose values are the numbers: the expression path, point by point.
  const auto varying = run_summary(dir, "varying", "--set 'fluid.Vmax=\"8 + 0*x\"' --set 'fluid.f=[\"0*y\", \"-981 + 0*t\"]'");
  ASSERT_EQ(numbers["status"], "converged");
  EXPECT_EQ(results(strings), results(numbers));
  EXPECT_EQ(results(varying), results(numbers));
  // The resolved case gives each key as it was given.
  EXPECT_EQ(numbers["parameters"]["fluid"]["Vmax"], 8.0);
  EXPECT_EQ(strings["parameters"]["fluid"]["Vmax"], "8.0");
  EXPECT_EQ(strings["parameters"]["structure"]["f"], nlohmann::json::parse(R"([0.0, "-10791.0"])"));
  EXPECT_EQ(varying["parameters"]["fluid"]["f"], nlohmann::json::parse(R"(["0*y", "-981 + 0*t"])"));
  // The written case.toml reruns to the same answer.
  const testing::CliRun again = testing::run_cli("run varying/case.toml -q --out again", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(results(nlohmann::json::parse(testing::slurp(dir / "again/summary.json"))), results(numbers));
  fs::remove_all(dir);
}

// Loads that vary in space: the fluid and the beam 20 % heavier at their right ends,
// the inflow 10 % stronger in the middle. Another answer, finite and converged (the
// coarse case's pressure and velocity in the structure move by tens of per cent).
TEST(ExpressionRun, LoadsThatVaryInSpaceGiveAnotherFiniteAnswer) {
  const fs::path dir = testing::scratch_dir("expression-varying");
  const auto numbers = run_summary(dir, "numbers", "");
  const auto varying = run_summary(dir, "varying", "--set 'fluid.f=[0, \"-981*(1 + 0.2*x/0.41)\"]' "
                                                    "--set 'structure.f=[0, \"-10791*(1 + 0.2*x/0.3)\"]' "
                                                    "--set 'fluid.Vmax=\"8*(1 + 0.1*sin(pi*x/0.41))\"'");
  ASSERT_EQ(varying["status"], "converged");
  for (const char* key : {"max_displacement", "fluid_velocity_l2_in_structure", "final_increment_l2"}) {
    const double a = numbers[key].get<double>(), b = varying[key].get<double>();
    EXPECT_TRUE(std::isfinite(b)) << key;
    EXPECT_NE(a, b) << key;
  }
  EXPECT_EQ(varying["parameters"]["fluid"]["Vmax"], "8*(1 + 0.1*sin(pi*x/0.41))");
  fs::remove_all(dir);
}

// sqrt(x − 0.2) is NaN left of x = 0.2: the fluid's load assembly meets it at a
// quadrature point. The run fails after validation, naming the key and the point.
TEST(ExpressionRun, ANaNOnTheWayFailsTheRunNamingTheKeyAndThePoint) {
  const fs::path dir = testing::scratch_dir("expression-nan");
  const auto j = run_summary(dir, "res", "--set 'fluid.f=[0, \"-981*sqrt(x - 0.2)\"]'", 1);
  EXPECT_EQ(j["status"], "failed");
  const std::string failure = j["failure"].get<std::string>();
  EXPECT_NE(failure.find("fluid.f (the y component) = \"-981*sqrt(x - 0.2)\" is nan at (x, y) = ("), std::string::npos)
      << failure;
  // The structure's load too: NaN right of x = 0.1.
  const auto s = run_summary(dir, "structure", "--set 'structure.f=[0, \"-10791*sqrt(0.1 - x)\"]'", 1);
  EXPECT_EQ(s["status"], "failed");
  EXPECT_NE(s["failure"].get<std::string>().find("structure.f (the y component) = \"-10791*sqrt(0.1 - x)\" is nan at"),
            std::string::npos)
      << s["failure"];
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::expression_run_test
