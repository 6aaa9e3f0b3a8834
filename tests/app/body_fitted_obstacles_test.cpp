// fluid.method = "body-fitted" with [[obstacles]] (issue 13; SPEC §9, §10): every
// obstacle a hole Sigma_5_i of the remeshed fluid, contact.gap = "normal", the fluid's
// force on each (obstacles[i].force), against the penalised method as the mesh is
// refined, and the refusal of a structure that comes too close to one of them.
// Base: cases/flap-between-two-disks.toml (the §7.2 beam between two disks), coarse.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::body_fitted_obstacles_test {
namespace {

namespace fs = std::filesystem;
const std::string kCase =
    std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/flap-between-two-disks.toml'";
const std::string kQuiet = " --set output.png=false --set output.vtu=false";

nlohmann::json run_ok(const std::string& args, const fs::path& dir, const std::string& out) {
  const testing::CliRun r = testing::run_cli("run " + args + kQuiet + " --out " + out, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(testing::slurp(dir / out / "summary.json"));
}

TEST(BodyFittedObstacles, TheFlapBetweenTwoDisksWithoutContact) {
  // The beam neutrally buoyant (structure.f = fluid.f) in a slow inflow: it bends by
  // under a millimetre, 2 cm from either disk.
  const fs::path dir = testing::scratch_dir("body-fitted-two-disks");
  const auto j =
      run_ok(kCase +
                 " --set fluid.method=body-fitted --set fluid.h=0.02 --set structure.h=0.03 "
                 "--set fluid.Vmax=0.5 --set structure.f=[0,-981] --set coupling.tol=1e-8",
             dir, "res");
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["contact"]["active_nodes"], 0);
  EXPECT_EQ(j["contact"]["gap"], "normal");
  // The gap (exact signed distance) stays above the 0.25 hF the method requires.
  EXPECT_GT(j["contact"]["min_gap"].get<double>(), 0.25 * 0.02);
  ASSERT_EQ(j["obstacles"].size(), 2u);  // Sigma_5_1 and Sigma_5_2, in the case's order
  // Each disk feels the fluid's body force f_F = (0, −981) as buoyancy, 981 π r² =
  // 7.70 N/m upward, less the area its ~16-sided meshed hole lacks (2.5 %) and plus
  // the slow flow's own force (~0.02 N/m, scaled from test (b)'s 0.3 N/m at Vmax = 8):
  // 4 % catches a sign error or a force taken on the wrong hole or on no hole.
  for (int i = 0; i < 2; ++i) {
    const auto& F = j["obstacles"][i]["force"];
    ASSERT_TRUE(F.is_array()) << i;
    EXPECT_NEAR(F[1].get<double>(), 981 * M_PI * 0.05 * 0.05, 0.04 * 7.70) << i;
    EXPECT_LT(std::abs(F[0].get<double>()), 0.1) << i;
  }
}

// |F_bf − F_pen| over both obstacles' forces, the structure at rest (the fluid alone).
double force_difference(const fs::path& dir, double h) {
  char sizes[160];
  std::snprintf(sizes, sizeof sizes, " --set fluid.h=%g --set structure.h=%g", h, 1.5 * h);
  const std::string common = kCase + sizes + " --set coupling.max_iterations=0 --set fluid.f=[0,0]";
  const auto bf = run_ok(common + " --set fluid.method=body-fitted", dir, "bf");
  const auto pen =
      run_ok(common + " --set fluid.method=penalised --set coupling.eps=1e-8", dir, "pen");
  double sum = 0;
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) {
      const double d = bf["obstacles"][i]["force"][k].get<double>() -
                       pen["obstacles"][i]["force"][k].get<double>();
      sum += d * d;
    }
  return std::sqrt(sum);
}

TEST(BodyFittedObstacles, TheObstacleForcesAgreeWithThePenalisedMethodAsTheMeshIsRefined) {
  // Two independent discretisations of the fluid around the beam at rest (no body
  // force: the paper's Vmax = 8 inflow alone; |F| ≈ 0.41 and 0.20 N/m): remeshed
  // around it, and penalised inside it (ε = 1e-8; 1e-10 moves the forces by 2e-7).
  // Measured (docs/validation.md, "Body-fitted check"): 0.0142, 0.00899, 0.00318 at
  // hF = 0.02, 0.01, 0.005, i.e. ratios 1.58 and 2.83 (rates 0.66, 1.50; on Gmsh's
  // meshes 0.0331, 0.0140, 0.00585: 1.24, 1.26). Each halving must divide it, the two
  // together by more than 4 (rate above 1); a force computed on the wrong hole, or with
  // the penalty's term in the body-fitted residual, does not converge.
  const fs::path dir = testing::scratch_dir("body-fitted-obstacle-forces");
  const double d1 = force_difference(dir, 0.02), d2 = force_difference(dir, 0.01),
               d3 = force_difference(dir, 0.005);
  EXPECT_GT(d1 / d2, 1.0) << d1 << " " << d2;
  EXPECT_GT(d2 / d3, 1.0) << d2 << " " << d3;
  EXPECT_GT(d1 / d3, 4.0) << d1 << " " << d3;
  EXPECT_LT(d3, 0.02 * 0.41) << "within 2 % of the larger force on the finest mesh";
}

// A run that ends as failed (exit 1, summary.json written) with a failure naming `what`.
void expect_failure_naming(const std::string& args, const fs::path& dir, const std::string& what) {
  const testing::CliRun r = testing::run_cli("run " + args + " --out res", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(j["status"], "failed");
  const std::string why = j["failure"];
  EXPECT_NE(why.find(what), std::string::npos) << why;
  EXPECT_NE(why.find("contact cannot be body-fitted"), std::string::npos) << why;
}

TEST(BodyFittedObstacles, RefusesAStructureThatComesTooCloseNamingTheObstacle) {
  const fs::path dir = testing::scratch_dir("body-fitted-obstacle-too-close");
  const std::string coarse =
      " --set fluid.method=body-fitted --set fluid.h=0.02 --set structure.h=0.03" + kQuiet;
  // Heavier than the fluid, the beam sinks towards the lower disk: at the third pass it
  // is 2.6 mm from it, below 0.25 hF = 5 mm (measured; at structure.f = (0, −2500) it
  // touches it in the first pass).
  expect_failure_naming(
      kCase + coarse + " --set fluid.Vmax=1 --set structure.f=[0,-2200] --set coupling.tol=1e-8",
      dir, "of obstacles[1]");
  // A polygon 3 mm above the beam at rest: refused at the first pass (the polygon's
  // distance to the outline), naming it.
  std::string text =
      testing::slurp(std::string(FSICONTACT_SOURCE_DIR) + "/cases/flap-between-two-disks.toml");
  const std::string upper = "shape = \"disk\"\nx0 = 0.15\ny0 = 0.1\nr = 0.05\n";
  ASSERT_NE(text.find(upper), std::string::npos);
  text.replace(
      text.find(upper), upper.size(),
      "shape = \"polygon\"\npoints = [[0.1, 0.033], [0.2, 0.033], [0.2, 0.08], [0.1, 0.08]]\n");
  const fs::path block = dir / "block";
  fs::create_directories(block);
  std::ofstream(block / "block.toml") << text;
  expect_failure_naming("block.toml" + coarse, block, "within 0.003 m of obstacles[2]");
}

}  // namespace
}  // namespace fsi::body_fitted_obstacles_test
