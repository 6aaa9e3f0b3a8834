// The fluid alone in time through `fsicontact run` (SPEC §12, run/time_fluid_problem.cpp):
// cases/dfg-2d3.toml on a coarse mesh and a few steps, its history, frames and
// summary; the ramped inflow's drag growing with it; Stokes in time; the refusals.
#include <gtest/gtest.h>

#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::time_run_test {
namespace {

namespace fs = std::filesystem;

const std::string kDfg2d3 = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/dfg-2d3.toml'";
const std::string kCoarse = " --set fluid.h=0.05 --set fluid.h_near=0.02 --set time.dt=0.1 --set time.t_end=0.5";

std::vector<std::string> lines(const fs::path& file) {
  std::vector<std::string> out;
  std::istringstream in(testing::slurp(file));
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Five steps of 0.1 s, a frame every second step and the last: frames at t = 0, 0.2,
// 0.4, 0.5 in fluid.pvd; one history line per step; the drag grows with the inflow
// (Vmax = 1.5 sin(πt/8) rises over these steps).
TEST(TimeRun, Dfg2d3sFirstStepsWriteHistoryFramesAndSummary) {
  const fs::path dir = testing::scratch_dir("time-dfg2d3");
  const testing::CliRun r =
      testing::run_cli("run " + kDfg2d3 + " -q --out res --set output.png=false --set time.output_every=2" + kCoarse, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["status"], "converged");
  EXPECT_EQ(s["time"]["steps"], 5);
  EXPECT_EQ(s["steps"], 5);  // SPEC §12's key
  EXPECT_DOUBLE_EQ(s["time"]["t"].get<double>(), 0.5);
  EXPECT_EQ(s["time"]["scheme"], "bdf2");
  EXPECT_EQ(s["parameters"]["time"]["dt"], 0.1);
  const std::vector<std::string> history = lines(dir / "res/history.csv");
  ASSERT_EQ(history.size(), 6u);
  EXPECT_EQ(history[0], "step,t,newton_steps,max_speed,obstacle_1_force_x,obstacle_1_force_y");
  double last_drag = 0;
  for (std::size_t k = 1; k < history.size(); ++k) {
    std::istringstream row(history[k]);
    std::vector<double> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 6u) << history[k];
    EXPECT_NEAR(cells[1], 0.1 * static_cast<double>(k), 1e-12);
    EXPECT_GE(cells[2], 1);  // Newton's steps
    EXPECT_GT(cells[4], last_drag) << "the drag grows with the inflow: " << history[k];
    last_drag = cells[4];
  }
  EXPECT_DOUBLE_EQ(s["obstacles"][0]["force"][0].get<double>(), last_drag);
  EXPECT_DOUBLE_EQ(s["obstacles"][0]["force_max"][0].get<double>(), last_drag);
  EXPECT_DOUBLE_EQ(s["obstacles"][0]["force_max_time"][0].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(s["obstacles"][0]["force_min_time"][0].get<double>(), 0.1);  // the first step's drag
  const std::string pvd = testing::slurp(dir / "res/fluid.pvd");
  for (const char* frame : {"timestep=\"0\" part=\"0\" file=\"fluid-000000.vtu\"", "timestep=\"0.2\" part=\"0\" file=\"fluid-000002.vtu\"",
                            "timestep=\"0.4\" part=\"0\" file=\"fluid-000004.vtu\"", "timestep=\"0.5\" part=\"0\" file=\"fluid-000005.vtu\""}) {
    EXPECT_NE(pvd.find(frame), std::string::npos) << frame << "\n" << pvd;
  }
  for (const char* file : {"fluid-000000.vtu", "fluid-000002.vtu", "fluid-000004.vtu", "fluid-000005.vtu", "fluid.vtu"})
    EXPECT_TRUE(fs::exists(dir / "res" / file)) << file;
  EXPECT_FALSE(fs::exists(dir / "res/fluid-000001.vtu"));
  fs::remove_all(dir);
}

// Stokes in time (ρ given, no convection): the symmetric solver, on the substructured
// factorisation by default (with χ = 0 it solves the whole system) and on the whole one.
TEST(TimeRun, StokesInTimeRunsOnTheSymmetricSolver) {
  const fs::path dir = testing::scratch_dir("time-stokes");
  const std::string run =
      "run " + kDfg2d3 + " -q --set output.png=false --set output.vtu=false --set fluid.model=stokes" + kCoarse;
  const testing::CliRun r = testing::run_cli(run + " --out res", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["time"]["steps"], 5);
  EXPECT_EQ(s["fluid"]["model"], "stokes");
  EXPECT_EQ(s["fluid"]["factorization"], "schur");
  const double drag = s["obstacles"][0]["force"][0].get<double>();
  EXPECT_GT(drag, 0);
  ASSERT_EQ(testing::run_cli(run + " --out whole --set fluid.factorization=whole", dir).status, 0);
  const auto w = nlohmann::json::parse(testing::slurp(dir / "whole/summary.json"));
  EXPECT_EQ(w["fluid"]["factorization"], "whole");
  EXPECT_NEAR(w["obstacles"][0]["force"][0].get<double>(), drag, 1e-12 * drag);
  fs::remove_all(dir);
}

// A rerun into the same directory with fewer frames leaves none of the first run's.
TEST(TimeRun, ARerunLeavesNoFrameOfTheEarlierRun) {
  const fs::path dir = testing::scratch_dir("time-rerun");
  const std::string run = "run " + kDfg2d3 + " -q --out res --set output.png=false" + kCoarse;
  ASSERT_EQ(testing::run_cli(run + " --set time.output_every=1", dir).status, 0);
  ASSERT_TRUE(fs::exists(dir / "res/fluid-000003.vtu"));
  ASSERT_EQ(testing::run_cli(run + " --set time.output_every=5", dir).status, 0);
  for (const char* stale : {"fluid-000001.vtu", "fluid-000002.vtu", "fluid-000003.vtu", "fluid-000004.vtu"})
    EXPECT_FALSE(fs::exists(dir / "res" / stale)) << stale;
  EXPECT_TRUE(fs::exists(dir / "res/fluid-000005.vtu"));
  EXPECT_EQ(testing::slurp(dir / "res/fluid.pvd").find("fluid-000001"), std::string::npos);
  fs::remove_all(dir);
}

// SIGTERM (a batch system's time limit) stops a time run after its current step with
// everything computed so far written: the history's steps, the frames with the last
// state among them, status "interrupted", exit status 128 + 15.
TEST(TimeRun, SigtermStopsAfterTheStepAndWritesWhatWasComputed) {
  const fs::path dir = testing::scratch_dir("time-sigterm");
  const pid_t pid = testing::spawn_cli({"run", std::string(FSICONTACT_SOURCE_DIR) + "/cases/dfg-2d3.toml", "--out", "res",
                                        "--set", "output.png=false", "--set", "fluid.h=0.05", "--set", "fluid.h_near=0.02",
                                        "--set", "time.output_every=100000"},
                                       dir, dir / "out.txt", dir / "err.txt");
  bool started = false;
  for (int wait = 0; wait < 1200 && !started; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started = testing::slurp(dir / "err.txt").find("[time] step") != std::string::npos;
  }
  ASSERT_TRUE(started) << testing::slurp(dir / "err.txt");
  ::kill(pid, SIGTERM);
  EXPECT_EQ(testing::wait_cli(pid), 128 + SIGTERM) << testing::slurp(dir / "err.txt");
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["status"], "interrupted");
  const int steps = s["time"]["steps"];
  EXPECT_GT(steps, 0);
  EXPECT_LT(steps, 400);
  EXPECT_EQ(lines(dir / "res/history.csv").size(), static_cast<std::size_t>(steps) + 1);
  char last[32];
  std::snprintf(last, sizeof last, "fluid-%06d.vtu", steps);
  EXPECT_TRUE(fs::exists(dir / "res" / last)) << last;
  EXPECT_NE(testing::slurp(dir / "res/fluid.pvd").find(last), std::string::npos);
  fs::remove_all(dir);
}

// A step whose Newton solve fails ends the run: exit 1, summary.json "failed" naming
// the step and its time, the steps before it kept (here none: the first fails).
TEST(TimeRun, AFailedStepIsAFailureNamingItsTime) {
  const fs::path dir = testing::scratch_dir("time-failed");
  const testing::CliRun r = testing::run_cli("run " + kDfg2d3 +
                                                 " -q --out res --set output.png=false --set fluid.newton_max_steps=1" +
                                                 kCoarse,
                                             dir);
  EXPECT_EQ(r.status, 1) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["status"], "failed");
  EXPECT_NE(s["failure"].get<std::string>().find("step 1 (t = 0.1 s)"), std::string::npos) << s["failure"];
  EXPECT_EQ(s["time"]["steps"], 0);
  EXPECT_TRUE(s["obstacles"][0]["force"].is_null());
  EXPECT_EQ(lines(dir / "res/history.csv").size(), 1u);  // the header alone
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::time_run_test
