// Polygon obstacles as holes of D in a coupled run, end to end (SPEC §9, §10), and a
// user's fluid mesh whose holes are the case's obstacles (fluid.mesh with
// [[obstacles]]): the flap of cases/flap-against-a-wedge.toml comes to rest on the
// wedge within the exact gap's tolerance, summary.json gives the fluid's force on it,
// and the figures are drawn; the same case on a .msh of the generated mesh (written
// here) gives the same answer; a file whose holes are not the case's is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/polygon.hpp"
#include "support/cli.hpp"
#include "support/msh.hpp"

namespace fsi::polygon_hole_run_test {
namespace {

namespace fs = std::filesystem;
const std::string kSource = FSICONTACT_SOURCE_DIR;
const std::vector<Point> kWedge = {{0.2, -0.12}, {0.34, -0.12}, {0.34, 0.0}};

nlohmann::json summary(const fs::path& dir) { return nlohmann::json::parse(testing::slurp(dir / "summary.json")); }

TEST(PolygonHoleRun, TheFlapRestsOnTheWedgeWithTheWedgesForce) {
  const fs::path dir = testing::scratch_dir("flap-wedge");
  const testing::CliRun r = testing::run_cli("run " + kSource + "/cases/flap-against-a-wedge.toml -q --out res", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = summary(dir / "res");
  EXPECT_EQ(j["status"], "converged");
  EXPECT_GE(j["contact"]["obstacles"][0]["active_nodes"].get<int>(), 1) << "the flap rests on the wedge";
  EXPECT_GE(j["contact"]["min_gap"].get<double>(), -1e-10 * std::hypot(0.3, 0.03));
  // The fluid's force on the wedge: upward, its buoyancy 981 |P| = 8.24 N/m less the
  // downward flow's drag (measured: 4.18 N/m).
  ASSERT_EQ(j["obstacles"].size(), 1u);
  const auto& F = j["obstacles"][0]["force"];
  ASSERT_TRUE(F.is_array()) << F;
  const double buoyancy = 981 * std::abs(signed_area(kWedge));
  EXPECT_TRUE(std::isfinite(F[0].get<double>()));
  EXPECT_GT(F[1].get<double>(), 0);
  EXPECT_LT(F[1].get<double>(), buoyancy);
  // The contact pushes the flap up and away from the flank (its normal (-0.65, 0.76)).
  EXPECT_LT(j["contact"]["obstacles"][0]["force"][0].get<double>(), 0);
  EXPECT_GT(j["contact"]["obstacles"][0]["force"][1].get<double>(), 0);
  for (const char* png : {"fsi.png", "structure.png"}) EXPECT_TRUE(fs::exists(dir / "res" / png)) << png;
  fs::remove_all(dir);
}

// The wedge case at coarse sizes with a disk above the flap too (two holes).
const std::string kTwoHoles = R"(name = "two-holes"
[structure]
h = 0.03
[fluid]
h = 0.02
left = "wall"
bottom = "outflow"
right = "wall"
top = "inflow"
[[obstacles]]
shape = "polygon"
points = [[0.2, -0.12], [0.34, -0.12], [0.34, 0.0]]
[[obstacles]]
shape = "disk"
x0 = 0.15
y0 = 0.1
r = 0.05
[coupling]
scheme = "aitken"
[contact]
gap = "normal"
boundary = "all"
)";

// What build_fluid_mesh generates for kTwoHoles (the paper's box at fluid.h = 0.02).
Mesh two_holes_mesh() {
  FluidGeometry g{0.41, 0.5, 0.5, 0, 0, 0, 0.02};
  g.holes = std::vector<FluidHole>{{0, 0, 0, kWedge}, {0.15, 0.1, 0.05}};
  return generate_fluid_mesh(g);
}

std::string with_mesh(const std::string& text, const std::string& file) {
  std::string out = text;
  return out.replace(out.find("[fluid]\n"), 8, "[fluid]\nmesh = \"" + file + "\"\n");
}

TEST(PolygonHoleRun, AFluidMeshWithTheObstaclesHolesGivesTheGeneratedAnswer) {
  const fs::path dir = testing::scratch_dir("holes-msh");
  testing::write_text(dir / "generated.toml", kTwoHoles);
  testing::write_text(dir / "file.toml", with_mesh(kTwoHoles, "holes.msh"));
  testing::write_text(dir / "holes.msh", testing::msh22(testing::hand_mesh(two_holes_mesh(), "D")));
  const testing::CliRun a = testing::run_cli("run generated.toml -q --out a", dir);
  const testing::CliRun b = testing::run_cli("run file.toml -q --out b", dir);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ja = summary(dir / "a"), jb = summary(dir / "b");
  EXPECT_EQ(ja["mesh"]["fluid"]["triangles"], jb["mesh"]["fluid"]["triangles"]);
  EXPECT_EQ(ja["iterations"], jb["iterations"]);
  EXPECT_NEAR(ja["max_displacement"].get<double>(), jb["max_displacement"].get<double>(), 1e-12);
  ASSERT_EQ(jb["obstacles"].size(), 2u);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) {
      const double fa = ja["obstacles"][i]["force"][k].get<double>(), fb = jb["obstacles"][i]["force"][k].get<double>();
      EXPECT_NEAR(fa, fb, 1e-9 * std::abs(fa)) << "obstacle " << i + 1 << " component " << k;
    }
  fs::remove_all(dir);
}

// One obstacle's hole may be named Sigma_5 (SPEC §10) and then is obstacles[1]'s.
TEST(PolygonHoleRun, OneObstaclesHoleMayBeNamedSigma5) {
  const fs::path dir = testing::scratch_dir("hole-sigma5");
  FluidGeometry g{0.41, 0.5, 0.5, 0, 0, 0, 0.02};
  g.holes = std::vector<FluidHole>{{0, 0, 0, kWedge}};
  testing::write_text(dir / "wedge.msh", testing::msh22(testing::hand_mesh(generate_fluid_mesh(g), "D", {{"Sigma_5_1", "Sigma_5"}})));
  std::string text = with_mesh(kTwoHoles, "wedge.msh");
  text.erase(text.find("[[obstacles]]\nshape = \"disk\""), std::string("[[obstacles]]\nshape = \"disk\"\nx0 = 0.15\ny0 = 0.1\nr = 0.05\n").size());
  testing::write_text(dir / "case.toml", text);
  const testing::CliRun r = testing::run_cli("run case.toml -q --out res", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = summary(dir / "res");
  ASSERT_EQ(j["obstacles"].size(), 1u);
  EXPECT_GT(j["obstacles"][0]["force"][1].get<double>(), 0) << "the wedge's buoyancy";
  fs::remove_all(dir);
}

struct Refused {
  const char* label;
  std::string case_text;
  std::vector<std::pair<std::string, std::string>> rename;  // of the file's groups
  std::vector<std::string> expected;                       // in the message
};

TEST(PolygonHoleRun, AFluidMeshWhoseHolesAreNotTheObstaclesIsRefused) {
  const fs::path dir = testing::scratch_dir("holes-msh-refused");
  const Mesh mesh = two_holes_mesh();
  auto moved = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  const std::string file = with_mesh(kTwoHoles, "holes.msh");
  const Refused cases[] = {
      {"a hole missing", file, {{"Sigma_5_2", "Sigma_6"}}, {"case.toml: fluid.mesh", "has no hole Sigma_5_2 for obstacles[2]"}},
      {"the disk elsewhere", moved(file, "x0 = 0.15", "x0 = 0.16"), {}, {"its hole Sigma_5_2 has the edge", "off the boundary of obstacles[2] (a disk)"}},
      {"the wedge elsewhere", moved(file, "[0.34, 0.0]]", "[0.34, 0.01]]"), {}, {"its hole Sigma_5_1", "off the boundary of obstacles[1] (a polygon)"}},
      {"the holes swapped", file, {{"Sigma_5_1", "Sigma_5_2"}, {"Sigma_5_2", "Sigma_5_1"}}, {"its hole Sigma_5_1", "obstacles[1]"}},
  };
  for (const Refused& c : cases) {
    testing::write_text(dir / "case.toml", c.case_text);
    testing::write_text(dir / "holes.msh", testing::msh22(testing::hand_mesh(mesh, "D", c.rename)));
    const testing::CliRun r = testing::run_cli("run case.toml -q --out res", dir);
    EXPECT_EQ(r.status, 2) << c.label << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.label << ": " << r.err;
    for (const std::string& s : c.expected) EXPECT_NE(r.err.find(s), std::string::npos) << c.label << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "res")) << c.label << ": nothing written";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::polygon_hole_run_test
