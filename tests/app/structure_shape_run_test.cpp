// structure.shape (SPEC §9) end to end: a structure from a Gmsh .geo script (Hertz's half
// cylinder on a floor) and from a .msh without structure.L and H run through
// `fsicontact run`; the resolved case.toml reruns to the same answer; summary.json names
// the shape and has no tip for a structure whose free end is not known.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/hertz_case.hpp"

namespace fsi::structure_shape_run_test {
namespace {

namespace fs = std::filesystem;

const std::string kSource = FSICONTACT_SOURCE_DIR;

const std::string kHertz = testing::hertz_case("0.2");

TEST(StructureShapeRun, AGeoScriptRunsAndRerunsFromItsCaseFile) {
  const fs::path dir = testing::scratch_dir("shape-geo");
  testing::write_text(dir / "hertz.toml", kHertz);
  const testing::CliRun r = testing::run_cli("run hertz.toml --out res -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(j["parameters"]["structure"]["shape"], "geo");
  EXPECT_NE(j["parameters"]["structure"]["geo"].get<std::string>().find("hertz-half-cylinder.geo"), std::string::npos);
  EXPECT_TRUE(j["tip_displacement"].is_null());
  EXPECT_GT(j["mesh"]["structure"]["triangles"].get<int>(), 500);
  EXPECT_GE(j["contact"]["active_nodes"].get<int>(), 3);
  EXPECT_GE(j["contact"]["min_gap"].get<double>(), -1e-10 * 2);
  const double Fy = j["contact"]["obstacles"][0]["force"][1].get<double>();
  EXPECT_NEAR(Fy, j["contact"]["pressure_resultant"].get<double>(), 1e-12);  // the floor pushes up: all of Γ_C's pressure
  EXPECT_GT(Fy, 0);
  const std::string png = testing::slurp(dir / "res/structure.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const std::string again_case = testing::slurp(dir / "res/case.toml");
  EXPECT_NE(again_case.find("shape = 'geo'"), std::string::npos) << again_case;
  EXPECT_EQ(again_case.find("L = "), std::string::npos) << "a script's extent is its own";
  const testing::CliRun again = testing::run_cli("run res/case.toml --out res2 -q", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  const auto j2 = nlohmann::json::parse(testing::slurp(dir / "res2/summary.json"));
  EXPECT_EQ(j2["max_displacement"], j["max_displacement"]);
  fs::remove_all(dir);
}

// A .msh without L and H: its extent is not checked against the defaults (0.3 × 0.03),
// and it gives the same answer as with the L and H it has.
TEST(StructureShapeRun, AMeshNeedsNoLengthAndHeight) {
  const fs::path dir = testing::scratch_dir("shape-mesh");
  const std::string base = "run " + kSource + "/cases/paper-7.1-fig5-msh.toml -q --set output.png=false --set output.vtu=false ";
  const testing::CliRun given = testing::run_cli(base + "--out given", dir);
  ASSERT_EQ(given.status, 0) << given.err;
  const std::string text = testing::slurp(kSource + "/cases/paper-7.1-fig5-msh.toml");
  ASSERT_NE(text.find("L = 0.06"), std::string::npos) << "the shipped case sets L";
  std::string without;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("L = ", 0) != 0 && line.rfind("H = ", 0) != 0) without += line + "\n";
  std::string::size_type at = without.find("mesh = \"");
  ASSERT_NE(at, std::string::npos);
  without.replace(at, 8, "shape = \"mesh\"\nmesh = \"" + kSource + "/cases/");
  testing::write_text(dir / "noLH.toml", without);
  const testing::CliRun r = testing::run_cli("run noLH.toml -q --set output.png=false --set output.vtu=false --out res", dir);
  ASSERT_EQ(r.status, 0) << r.err << without;
  const auto a = nlohmann::json::parse(testing::slurp(dir / "given/summary.json"));
  const auto b = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(a["max_displacement"], b["max_displacement"]);
  EXPECT_TRUE(b["tip_displacement"].is_null());
  EXPECT_FALSE(a["tip_displacement"].is_null());
  fs::remove_all(dir);
}

// The documented examples of issue 13 run, touch what they say they touch and draw it.
TEST(StructureShapeRun, TheContactExamplesRun) {
  const fs::path dir = testing::scratch_dir("shape-examples");
  for (const char* name : {"block-on-a-wedge", "capsule-against-a-wall", "beam-on-two-disks"}) {
    const testing::CliRun r = testing::run_cli("run " + kSource + "/cases/" + name + ".toml -q --out " + name, dir);
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    const auto j = nlohmann::json::parse(testing::slurp(dir / name / "summary.json"));
    for (const auto& o : j["contact"]["obstacles"]) EXPECT_GT(o["active_nodes"].get<int>(), 0) << name;
    EXPECT_GE(j["contact"]["min_gap"].get<double>(), -1e-12) << name;
    EXPECT_GT(j["contact"]["pressure_resultant"].get<double>(), 0) << name;
    EXPECT_TRUE(fs::exists(dir / name / "structure.png")) << name;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::structure_shape_run_test
