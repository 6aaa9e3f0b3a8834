// fluid.h_near and fluid.band through the command line (coarse §7.2): the band's box
// is the structure at rest and at its load-alone contact solution grown by the width,
// or the user's box; it refines the fluid mesh and is reported in summary.json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::band_run_test {
namespace {

namespace fs = std::filesystem;
const std::string kCoarse =
    "--set fluid.h=0.02 --set structure.h=0.01 --set fluid.chi=area-fraction --set coupling.scheme=aitken -q --set output.png=false";

nlohmann::json run(const std::string& name, const std::string& args) {
  const fs::path dir = testing::scratch_dir(name);
  const testing::CliRun r = testing::run_cli("run " + kCoarse + " " + args + " --out res", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  fs::remove_all(dir);
  return j;
}

TEST(BandRun, AWidthAroundTheStructureAtRestAndUnderItsLoads) {
  const auto uniform = run("band-none", "");
  const auto j = run("band-width", "--set fluid.h_near=0.005 --set fluid.band=0.01");
  const auto& f = j["mesh"]["fluid"];
  ASSERT_TRUE(f.contains("band_box")) << f.dump();
  EXPECT_FALSE(uniform["mesh"]["fluid"].contains("band_box"));
  const auto box = f["band_box"].get<std::array<double, 4>>();
  EXPECT_EQ(box[0], 0.0);                      // clipped to Σ1, where the beam is clamped
  // The beam's end: bent down, its end section turns and its top corner moves right.
  EXPECT_GT(box[2], 0.3 + 0.01);
  EXPECT_LT(box[2], 0.3 + 0.01 + 0.005);
  EXPECT_NEAR(box[3], 0.03 + 0.01, 1e-12);     // its top at rest: the loads push it down
  // Its bottom under gravity alone: the beam lies on the disk, whose top is at
  // y = -0.02 (§7.2: y0 = -0.07, r = 0.05), and its free end bends below that.
  EXPECT_LT(box[1], -0.02 - 0.01);
  EXPECT_GT(box[1], -0.07 - 0.01);
  EXPECT_TRUE(f["band_warning"].is_null()) << f["band_warning"];
  EXPECT_EQ(f["h_near"], 0.005);
  // The band holds about 2.4 · area / h_near² more triangles, and the transition
  // around it some more.
  const double area = (box[2] - box[0]) * (box[3] - box[1]);
  const int added = f["triangles"].get<int>() - uniform["mesh"]["fluid"]["triangles"].get<int>();
  EXPECT_GT(added, 0.6 * 2.4 * area / (0.005 * 0.005));
  EXPECT_LT(added, 2.0 * 2.4 * area / (0.005 * 0.005));
  EXPECT_LE(f["h_max"].get<double>(), 1.5 * 0.02);
}

TEST(BandRun, AUserBoxAndATooNarrowBandIsSaid) {
  const auto j = run("band-box", "--set fluid.h_near=0.005 --set 'fluid.band=[0, 0, 0.2, 0.04]'");
  const auto& f = j["mesh"]["fluid"];
  const std::array<double, 4> expected = {0, 0, 0.2, 0.04};
  const auto box = f["band_box"].get<std::array<double, 4>>();
  EXPECT_EQ(box, expected);
  // The beam leaves this box (its end at x = 0.3, bent below y = 0).
  ASSERT_TRUE(f["band_warning"].is_string());
  EXPECT_NE(f["band_warning"].get<std::string>().find("fluid.band"), std::string::npos);
}

}  // namespace
}  // namespace fsi::band_run_test
