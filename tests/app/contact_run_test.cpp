// A contact-only run end to end: exit status 0, the three outputs, and every key
// SPEC §8 promises users' scripts.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::contact_run_test {
namespace {

namespace fs = std::filesystem;

TEST(ContactRun, WritesSummaryVtuAndPng) {
  const fs::path dir = testing::scratch_dir("contact-run");
  const std::string case_path = std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.1-fig5-coarse.toml";
  const testing::CliRun r = testing::run_cli("run '" + case_path + "' --out res", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Contact on"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("[structure] active-set it"), std::string::npos) << "no progress lines";

  const auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  for (const char* key : {"name", "parameters", "mesh", "converged", "iterations", "max_displacement",
                          "min_displacement_y", "contact", "kkt", "timing_s"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"triangles", "vertices", "min_angle_deg"})
    EXPECT_TRUE(j["mesh"]["structure"].contains(key)) << key;
  for (const char* key : {"active_nodes", "x_min", "x_max", "max_multiplier"})
    EXPECT_TRUE(j["contact"].contains(key)) << key;
  for (const char* key : {"stationarity", "feasibility", "complementarity"})
    EXPECT_TRUE(j["kkt"].contains(key)) << key;
  for (const char* key : {"total", "mesh", "fluid", "structure", "transfer"})
    EXPECT_TRUE(j["timing_s"].contains(key)) << key;
  EXPECT_FALSE(j.contains("fluid_velocity_l2_in_structure")) << "contact-only runs omit fluid keys";
  EXPECT_EQ(j["converged"], true);
  EXPECT_GE(j["contact"]["active_nodes"].get<int>(), 1);
  EXPECT_LT(j["min_displacement_y"].get<double>(), -0.007);  // touches the arc's top at y = −0.007

  const std::string vtu = testing::slurp(dir / "res/structure.vtu");
  for (const char* field : {"displacement", "von_mises", "contact_multiplier", "contact_status"})
    EXPECT_NE(vtu.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;
  EXPECT_NE(vtu.find("</VTKFile>"), std::string::npos);
  const std::string png = testing::slurp(dir / "res/structure.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // The resolved case is written beside the results and reruns to the same answer.
  ASSERT_TRUE(fs::exists(dir / "res/case.toml"));
  const testing::CliRun again = testing::run_cli("run res/case.toml --out res2 -q", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  const auto j2 = nlohmann::json::parse(testing::slurp(dir / "res2/summary.json"));
  EXPECT_EQ(j2["max_displacement"], j["max_displacement"]);
  // No temporary files left behind.
  for (const auto& e : fs::directory_iterator(dir / "res"))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::contact_run_test
