// The structure alone in time through `fsicontact run` (SPEC §12,
// run/time_structure_problem.cpp): the bar impact of Doyen, Ern & Piperno (2011) against
// its closed form (contact for 2L/c, stress ρ c v0, rebound at v0, energy kept) with the
// mass redistributed, plain Newmark's consistent mass chattering and gaining energy
// (why it is not the default), the outputs, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/history.hpp"

namespace fsi::structure_time_run_test {
namespace {

namespace fs = std::filesystem;

const std::string kBar = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/bar-impact.toml'";
// The bar's exact answer (the case's numbers): L = 1, H = 0.1, c = sqrt(E/ρ) = 10, v0 = 0.1.
constexpr double kL = 1.0, kH = 0.1, kC = 10.0, kV0 = 0.1, kRho = 1.0;

using testing::History;
using testing::read_history;

// h = 0.01, Δt = 5e-4 (c Δt / h = 0.5), to t = 0.32 (the bar leaves at 0.30): 640 steps,
// about 1 s (15 s under the sanitizers before it stopped at 0.32 instead of 0.45).
TEST(StructureTimeRun, TheBarImpactMeetsItsClosedForm) {
  const fs::path dir = testing::scratch_dir("bar-impact");
  const testing::CliRun r = testing::run_cli(
      "run " + kBar + " -q --out res --set structure.h=0.01 --set time.dt=5e-4 --set time.t_end=0.32 --set time.output_every=300",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["status"], "converged");
  EXPECT_EQ(s["steps"], 640);
  EXPECT_EQ(s["time"]["mass"], "redistributed");
  ASSERT_EQ(s["contact_intervals"].size(), 1u) << s["contact_intervals"];
  const auto& contact = s["contact_intervals"][0];
  EXPECT_NEAR(contact["start"].get<double>(), 0.1, 1e-3);  // the gap 0.01 m at v0
  EXPECT_NEAR(contact["duration"].get<double>(), 2 * kL / kC, 0.02 * 2 * kL / kC);
  EXPECT_NEAR(contact["velocity_before"][0].get<double>(), -kV0, 1e-12);
  EXPECT_NEAR(contact["velocity_after"][0].get<double>(), kV0, 0.02 * kV0);
  EXPECT_LT(s["energy"]["max_relative_drift"].get<double>(), 1e-4);
  // The stress plateau: the contact force over H, averaged over the middle 60 % of the
  // contact (the discrete front's ringing averages out).
  const History h = read_history(dir / "res/history.csv");
  ASSERT_EQ(h.rows.size(), 641u);  // the initial state and every step
  const double t0 = contact["start"], t1 = contact["end"];
  double sum = 0;
  int count = 0;
  for (const auto& row : h.rows) {
    const double t = row[h.column("t")];
    if (t >= t0 + 0.2 * (t1 - t0) && t <= t1 - 0.2 * (t1 - t0)) sum += row[h.column("contact_fx")], ++count;
  }
  ASSERT_GT(count, 100);
  EXPECT_NEAR(sum / count / kH, kRho * kC * kV0, 0.05 * kRho * kC * kV0);
  for (const char* file : {"structure-000000.vtu", "structure-000300.vtu", "structure-000640.vtu", "structure.vtu",
                           "structure.pvd", "structure.png", "case.toml"})
    EXPECT_TRUE(fs::exists(dir / "res" / file)) << file;
  EXPECT_NE(testing::slurp(dir / "res/structure.pvd").find("timestep=\"0.15\" part=\"0\" file=\"structure-000300.vtu\""),
            std::string::npos);
  fs::remove_all(dir);
}

// Plain Newmark with the consistent mass: the contact nodes' velocities jump at every
// step in contact, the bar chatters (many contact intervals) and gains energy.
// Measured (docs/validation.md, "Bar impact"): 35 intervals and 12× the energy at h = 0.02.
TEST(StructureTimeRun, PlainNewmarksConsistentMassChattersAndGainsEnergy) {
  const fs::path dir = testing::scratch_dir("bar-consistent");
  const testing::CliRun r = testing::run_cli(
      "run " + kBar + " -q --out res --set structure.mass=consistent --set output.vtu=false --set output.png=false", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_GT(s["contact_intervals"].size(), 5u);
  EXPECT_GT(s["energy"]["final"].get<double>(), 2 * s["energy"]["initial"].get<double>());
  fs::remove_all(dir);
}

// Each refused with exit 2, the key named, nothing written.
TEST(StructureTimeRun, RefusesWhatATimeRunOfTheStructureCannotDo) {
  const fs::path dir = testing::scratch_dir("structure-time-refusals");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set structure.rho=nan", "structure.rho"},
      {"--set structure.clamped=false --set time.dt=0 ", "time.dt"},
      {"--set structure.element=P2", "structure.mass"},
      {"--set structure.mass=lumped", "structure.mass"},
      {"--set structure.v0=[1]", "structure.v0"},
  };
  for (const auto& [set, key] : cases) {
    const testing::CliRun r = testing::run_cli("run " + kBar + " -q --out res " + set, dir);
    EXPECT_EQ(r.status, 2) << set << "\n" << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << set << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "res")) << set;
  }
  // Without [time]: a free body is refused; with a fluid, the fluid's density is required.
  const std::string steady = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/paper-7.2.toml'";
  testing::CliRun r = testing::run_cli("run " + steady + " -q --out res --set structure.clamped=false", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("structure.clamped"), std::string::npos) << r.err;
  r = testing::run_cli("run " + steady + " -q --out res --set time.dt=0.1 --set time.t_end=1 --set structure.rho=1000", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("fluid.rho"), std::string::npos) << r.err;
  r = testing::run_cli("run '" + std::string(FSICONTACT_SOURCE_DIR) +
                           "/cases/turek-hron-csm1.toml' -q --out res --set time.dt=0.1 --set time.t_end=1",
                       dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("structure.rho"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "res"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::structure_time_run_test
