// Steady Navier–Stokes end to end (SPEC §10), through `fsicontact run` on the shipped
// cases: the DFG 2D-1 drag and lift on a coarse mesh, Newton's report in
// summary.json, a Reynolds number with no steady flow found is a failure with the
// residual history, and a contact case where inertia changes the answer.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::navier_stokes_run_test {
namespace {

namespace fs = std::filesystem;

const std::string kCases = std::string(FSICONTACT_SOURCE_DIR) + "/cases/";

struct Outcome {
  int status;
  std::string err;
  nlohmann::json summary;
};

Outcome run(const std::string& name, const std::string& args) {
  const fs::path dir = testing::scratch_dir("navier-stokes-" + name);
  const testing::CliRun r =
      testing::run_cli("run " + kCases + name + ".toml -q --out res --set output.png=false --set output.vtu=false " + args, dir);
  const fs::path summary = dir / "res/summary.json";
  return {r.status, r.err, fs::exists(summary) ? nlohmann::json::parse(testing::slurp(summary)) : nlohmann::json()};
}

// cases/dfg-2d1.toml at a quarter of its sizes (about 3 000 triangles): C_D within
// 1 % and C_L within 15 % of Schäfer & Turek's (docs/validation.md has the study that
// meets 1e-4 and 2 %); Newton from rest in a handful of steps, quadratically.
TEST(NavierStokesRun, Dfg2d1DragAndLiftOnACoarseMesh) {
  const Outcome r = run("dfg-2d1", "--set fluid.h=0.04 --set fluid.h_near=0.01");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto& s = r.summary;
  EXPECT_EQ(s["parameters"]["fluid"]["model"], "navier-stokes");
  EXPECT_EQ(s["parameters"]["fluid"]["viscous_form"], "gradient");
  const double C_D = 500 * s["obstacles"][0]["force"][0].get<double>();  // 2 / (ρ Ū² D)
  const double C_L = 500 * s["obstacles"][0]["force"][1].get<double>();
  EXPECT_NEAR(C_D, 5.57953523384, 0.01 * 5.58);
  EXPECT_NEAR(C_L, 0.010618948146, 0.15 * 0.0106);
  const auto& n = s["fluid"]["newton"];
  EXPECT_EQ(s["fluid"]["solver"], "mumps-lu");
  EXPECT_LE(n["steps"].get<int>(), 8);
  EXPECT_LE(n["max_final_residual"].get<double>(), 1e-10);
  EXPECT_EQ(s["fluid"]["analyses"], 1);  // one symbolic analysis for every step
  EXPECT_NEAR(s["fluid"]["reynolds"]["value"].get<double>(), 20.0, 1e-9);  // ρ (2 Vmax / 3) D / μ
  // Δp between the cylinder's front and back points (output.fluid_probes): within 10 %.
  const double dp = s["fluid_at"][0]["p"].get<double>() - s["fluid_at"][1]["p"].get<double>();
  EXPECT_NEAR(dp, 0.11752016697, 0.1 * 0.1175);
}

// fluid.element = "taylor-hood" on the same coarse mesh: P2/P1 with the cylinder
// curved. Its drag is an order closer to the reference than the mini element's there
// (measured at about 3 000 triangles: C_D −2.4e-4 relative against the mini element's
// −3.5e-3, C_L −4.7 % against −7.3 %; at 12 000 triangles −3e-5 and −1e-5,
// docs/validation.md).
TEST(NavierStokesRun, TaylorHoodOnTheSameMeshIsFarCloser) {
  const Outcome th = run("dfg-2d1", "--set fluid.h=0.04 --set fluid.h_near=0.01 --set fluid.element=taylor-hood");
  const Outcome mini = run("dfg-2d1", "--set fluid.h=0.04 --set fluid.h_near=0.01");
  ASSERT_EQ(th.status, 0) << th.err;
  ASSERT_EQ(mini.status, 0) << mini.err;
  const auto& s = th.summary;
  EXPECT_EQ(s["fluid"]["element"], "taylor-hood");
  EXPECT_EQ(mini.summary["fluid"]["element"], "mini");
  EXPECT_GT(s["fluid"]["curved_triangles"].get<int>(), 20);
  EXPECT_EQ(s["mesh"]["fluid"]["triangles"], mini.summary["mesh"]["fluid"]["triangles"]);
  const auto coefficients = [](const nlohmann::json& summary) {
    const auto& F = summary["obstacles"][0]["force"];
    return std::array<double, 2>{500 * F[0].get<double>(), 500 * F[1].get<double>()};
  };
  const auto [C_D, C_L] = coefficients(s);
  const auto [mini_C_D, mini_C_L] = coefficients(mini.summary);
  std::printf("C_D %.7f (mini %.7f), C_L %.7f (mini %.7f)\n", C_D, mini_C_D, C_L, mini_C_L);
  EXPECT_NEAR(C_D, 5.57953523384, 4e-4 * 5.58);
  EXPECT_NEAR(C_L, 0.010618948146, 0.06 * 0.0106);
  EXPECT_LT(std::abs(C_L - 0.010618948146), std::abs(mini_C_L - 0.010618948146));
  EXPECT_LT(std::abs(C_D - 5.57953523384), 0.1 * std::abs(mini_C_D - 5.57953523384));
  EXPECT_LE(s["fluid"]["newton"]["steps"].get<int>(), 8);
  EXPECT_LE(s["fluid"]["newton"]["max_final_residual"].get<double>(), 1e-10);
  const double dp = s["fluid_at"][0]["p"].get<double>() - s["fluid_at"][1]["p"].get<double>();
  EXPECT_NEAR(dp, 0.11752016697, 0.01 * 0.1175);
}

// The pictures: the whole box and the cylinder's wake, where the flow separates.
TEST(NavierStokesRun, DrawsTheWake) {
  const fs::path dir = testing::scratch_dir("navier-stokes-wake");
  const testing::CliRun r =
      testing::run_cli("run " + kCases + "dfg-2d1.toml -q --out res --set fluid.h=0.04 --set fluid.h_near=0.02 --set output.vtu=false", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(fs::file_size(dir / "res/fluid.png"), 10000u);
  EXPECT_GT(fs::file_size(dir / "res/fluid-wake.png"), 10000u);
}

// Re = 2000 in the DFG channel: no steady flow from rest; newton_max_steps bounds the
// work, and summary.json says "failed" with the residual history.
// Both elements alike.
TEST(NavierStokesRun, NoSteadyFlowIsAFailureWithTheResidualHistory) {
  for (const char* element : {"mini", "taylor-hood"}) {
    const Outcome r = run("dfg-2d1", "--set fluid.h=0.04 --set fluid.h_near=0.02 --set fluid.rho=100 "
                          "--set fluid.newton_max_steps=3 --set fluid.element=" + std::string(element));
    EXPECT_EQ(r.status, 1) << element << r.err;
    ASSERT_TRUE(r.summary.is_object()) << element;
    EXPECT_EQ(r.summary["status"], "failed") << element;
    EXPECT_NE(r.summary["failure"].get<std::string>().find("Reynolds"), std::string::npos) << element;
    EXPECT_EQ(r.summary["fluid"]["newton"]["last_residuals"].size(), 4u) << element;
    EXPECT_EQ(r.summary["obstacles"][0]["force"], nullptr) << element;
  }
}

// The flap of cases/flap-against-a-wedge-inertia.toml pressed onto the wedge by the
// flow alone, at Re ≈ 140: inertia raises the contact force by about a third over
// creeping flow (Stokes) on the same meshes (coarser than the case's, for the
// sanitizers' build); both converge.
TEST(NavierStokesRun, InertiaPressesTheFlapHarderOntoTheWedge) {
  const std::string coarse = "--set fluid.h=0.02 --set structure.h=0.03";
  const Outcome ns = run("flap-against-a-wedge-inertia", coarse);
  const Outcome stokes = run("flap-against-a-wedge-inertia", coarse + " --set fluid.model=stokes");
  ASSERT_EQ(ns.status, 0) << ns.err;
  ASSERT_EQ(stokes.status, 0) << stokes.err;
  const double F_ns = ns.summary["contact"]["pressure_resultant"].get<double>();
  const double F_stokes = stokes.summary["contact"]["pressure_resultant"].get<double>();
  EXPECT_GT(F_stokes, 0);
  EXPECT_GT(F_ns, 1.2 * F_stokes);
  EXPECT_GT(ns.summary["contact"]["active_nodes"].get<int>(), 0);
}

}  // namespace
}  // namespace fsi::navier_stokes_run_test
