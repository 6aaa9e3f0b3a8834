// structure.shape = "none" (SPEC §9): the fluid alone in its box with its holes, through
// `fsicontact run`: no structure keys in the summary, the fluid's force on each
// obstacle (SPEC §10), exact for a fluid at rest (buoyancy), converging with the mesh
// for a flow past the paper's disk.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::fluid_alone_run_test {
namespace {

namespace fs = std::filesystem;

nlohmann::json run_fluid(const fs::path& dir, const std::string& text, const std::string& args) {
  testing::write_text(dir / "case.toml", text);
  const testing::CliRun r = testing::run_cli("run case.toml -q --out res " + args, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
}

// At rest (Vmax = 0) under gravity the discrete fluid is hydrostatic and each hole's
// force is its buoyancy, up to the meshed circle's area (a polygon of ~2πr/h sides).
TEST(FluidAloneRun, AtRestEachHoleFeelsItsBuoyancy) {
  const fs::path dir = testing::scratch_dir("fluid-alone-rest");
  const auto j = run_fluid(dir, R"(name = "rest"
[structure]
shape = "none"
[fluid]
Vmax = 0.0
h = 0.01
[[obstacles]]
shape = "disk"
x0 = 0.12
y0 = 0.1
r = 0.05
[[obstacles]]
shape = "disk"
x0 = 0.28
y0 = -0.2
r = 0.08
)", "--set output.png=false --set output.vtu=false");
  EXPECT_EQ(j["problem"], "fluid");
  EXPECT_EQ(j["status"], "converged");
  EXPECT_FALSE(j.contains("max_displacement"));
  EXPECT_FALSE(j["mesh"].contains("structure"));
  ASSERT_EQ(j["obstacles"].size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const double r = i == 0 ? 0.05 : 0.08;
    const double buoyancy = 9.81 * 100 * std::numbers::pi * r * r;
    const auto& F = j["obstacles"][i]["force"];
    EXPECT_NEAR(F[1].get<double>(), buoyancy, 0.01 * buoyancy) << i;  // the polygon's area: −0.7 % at 31 sides
    EXPECT_LT(F[1].get<double>(), buoyancy) << i;                       // inscribed: smaller than the disk
    EXPECT_NEAR(F[0].get<double>(), 0.0, 1e-9 * buoyancy) << i;
  }
  fs::remove_all(dir);
}

// The paper's box and disk without the beam: the downward flow drags the disk down
// and along its off-centre side; the drag changes by under 2 % from hF = 0.02 to 0.01.
TEST(FluidAloneRun, TheFlowPastThePapersDiskConverges) {
  const fs::path dir = testing::scratch_dir("fluid-alone-flow");
  const std::string text = "name = \"flow\"\n[structure]\nshape = \"none\"\n[fluid]\nf = [0.0, 0.0]\n";
  const auto coarse = run_fluid(dir, text, "--set fluid.h=0.02");
  ASSERT_TRUE(fs::exists(dir / "res/fluid.png"));
  ASSERT_TRUE(fs::exists(dir / "res/fluid.vtu"));
  ASSERT_TRUE(fs::exists(dir / "res/case.toml"));
  const auto fine = run_fluid(dir, text, "--set fluid.h=0.01 --set output.png=false");
  ASSERT_EQ(fine["obstacles"].size(), 1u);  // [obstacle]'s disk
  const double Fy_c = coarse["obstacles"][0]["force"][1].get<double>(), Fy_f = fine["obstacles"][0]["force"][1].get<double>();
  EXPECT_LT(Fy_f, 0.0);  // the inflow at the top pushes it down
  EXPECT_LT(std::abs(Fy_c - Fy_f), 0.02 * std::abs(Fy_f)) << Fy_c << " " << Fy_f;
  EXPECT_LT(std::abs(fine["obstacles"][0]["force"][0].get<double>()), 0.2 * std::abs(Fy_f));
  // The written case reruns to the same answer.
  const testing::CliRun again = testing::run_cli("run res/case.toml -q --out res2 --set output.png=false --set output.vtu=false", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  const auto j2 = nlohmann::json::parse(testing::slurp(dir / "res2/summary.json"));
  EXPECT_EQ(j2["obstacles"], fine["obstacles"]);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::fluid_alone_run_test
