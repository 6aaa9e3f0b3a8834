// Checkpoints and --resume (SPEC §12): a time run stopped by SIGTERM mid-run (a real
// signal at a known step: FSICONTACT_FAULT=sigterm@N, common/fault.hpp) writes what it
// computed and a checkpoint; `fsicontact run CASE --resume DIR` continues from it to
// the same answer, bit for bit, as an uninterrupted run: history.csv, every frame and
// its collection, the final fields and summary.json (but its timings, its work
// counters and "resumed"). For each kind of time run: the structure alone, the fluid
// alone (Navier–Stokes, BDF2: Newton's start and two levels of history), and both
// coupled (IQN-ILS keeping its secant pairs across steps). And the refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::time_resume_test {
namespace {

namespace fs = std::filesystem;

const std::string kCases = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/";

std::string bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// summary.json without what counts this process's work rather than the answer.
nlohmann::json answer(const fs::path& dir) {
  auto s = nlohmann::json::parse(testing::slurp(dir / "summary.json"));
  s.erase("timing_s"), s.erase("resumed"), s.erase("timing");
  s["parameters"]["output"].erase("dir");
  if (s.contains("fluid")) {
    for (const char* key : {"analyses", "factorizations", "reused_solutions", "assembly_s", "analysis_s",
                            "factorization_s", "solve_s", "far_factorization_s", "expansion_s", "newton",
                            "far_field_factorizations", "far_field_refactorizations", "chord_steps"})
      s["fluid"].erase(key);
  }
  return s;
}

// Every file of `a` but the checkpoint and summary.json is in `b` with the same bytes,
// and `b` has no other.
void expect_same_outputs(const fs::path& a, const fs::path& b) {
  std::size_t compared = 0;
  for (const auto& e : fs::directory_iterator(a)) {
    const std::string name = e.path().filename().string();
    if (name == "summary.json" || name == "checkpoint.bin" || name.front() == '.') continue;
    ASSERT_TRUE(fs::exists(b / name)) << name << " missing after the resume";
    if (name == "case.toml") continue;  // its output.dir differs
    EXPECT_TRUE(bytes(a / name) == bytes(b / name)) << name << " differs after the resume";
    ++compared;
  }
  for (const auto& e : fs::directory_iterator(b)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name.front() == '.' || fs::exists(a / name)) << name << " is only in the resumed run";
  }
  EXPECT_GE(compared, 5u);
  EXPECT_EQ(answer(a), answer(b));
}

// Runs `args` whole in a/, stopped by SIGTERM at `stop` in b/, resumed there; the two
// must agree. Returns the resumed run's summary.
nlohmann::json run_stop_resume(const std::string& name, const std::string& args, int stop, int checkpoint_step) {
  const fs::path dir = testing::scratch_dir(name);
  const testing::CliRun whole = testing::run_cli(args + " -q --out a", dir);
  EXPECT_EQ(whole.status, 0) << whole.err;
  if (args.find("output.png=false") == std::string::npos) {  // compared with the rest below
    EXPECT_TRUE(fs::exists(dir / "a/animation.gif"));
    EXPECT_TRUE(fs::exists(dir / "a/frame-000000.png"));
  }
  const testing::CliRun stopped =
      testing::run_shell("FSICONTACT_FAULT=sigterm@" + std::to_string(stop) + " '" + FSICONTACT_BINARY + "' " + args +
                             " -q --out b",
                         dir);
  EXPECT_EQ(stopped.status, 143) << stopped.err;  // 128 + SIGTERM
  const auto s = nlohmann::json::parse(testing::slurp(dir / "b/summary.json"));
  EXPECT_EQ(s["status"], "interrupted");
  EXPECT_EQ(s["steps"], checkpoint_step);
  EXPECT_TRUE(fs::exists(dir / "b/checkpoint.bin"));
  EXPECT_TRUE(fs::exists(dir / "b/history.csv"));
  // The stopped run's last state is a frame too (off the series' grid here), which the
  // resumed run removes: it writes the series an uninterrupted run would have.
  char last[32];
  std::snprintf(last, sizeof last, "-%06d.vtu", checkpoint_step);
  const std::string kind = fs::exists(dir / "a/structure.pvd") ? "structure" : "fluid";
  EXPECT_TRUE(fs::exists(dir / "b" / (kind + last))) << kind + last;
  EXPECT_NE(testing::slurp(dir / "b" / (kind + ".pvd")).find(kind + last), std::string::npos);
  const testing::CliRun resumed = testing::run_cli(args + " -q --resume b", dir);
  EXPECT_EQ(resumed.status, 0) << resumed.err;
  expect_same_outputs(dir / "a", dir / "b");
  return nlohmann::json::parse(testing::slurp(dir / "b/summary.json"));
}

TEST(TimeResume, TheStructureAloneContinuesBitForBit) {
  const auto s = run_stop_resume(
      "resume-structure",
      "run " + kCases + "bar-impact.toml' --set structure.h=0.02 --set time.dt=1e-3 --set time.t_end=0.3 "
      "--set time.output_every=40 --set time.checkpoint_every=50",
      137, 137);
  EXPECT_EQ(s["resumed"]["step"], 137);
  EXPECT_EQ(s["steps"], 300);
  ASSERT_EQ(s["contact_intervals"].size(), 1u);  // the impact straddles the stop
}

TEST(TimeResume, TheFluidAloneContinuesBitForBit) {
  const auto s = run_stop_resume(
      "resume-fluid",
      "run " + kCases + "dfg-2d2.toml' --set fluid.h=0.05 --set fluid.h_near=0.025 --set fluid.mesher=lattice "
      "--set time.dt=0.02 --set time.t_end=0.16 --set time.output_every=3 --set output.png=false",
      4, 4);
  EXPECT_EQ(s["steps"], 8);
}

// The Taylor–Hood march's checkpoint (its P2 states, and the state its reused factors
// were computed at) continues the same way.
TEST(TimeResume, TheTaylorHoodFluidContinuesBitForBit) {
  const auto s = run_stop_resume(
      "resume-taylor-hood",
      "run " + kCases + "dfg-2d2.toml' --set fluid.element=taylor-hood --set fluid.h=0.05 --set fluid.h_near=0 "
      "--set fluid.mesher=lattice --set time.dt=0.02 --set time.t_end=0.08 --set time.output_every=1 --set output.png=false",
      2, 2);
  EXPECT_EQ(s["steps"], 4);
  EXPECT_EQ(s["fluid"]["element"], "taylor-hood");
  EXPECT_GT(s["fluid"]["chord_steps"], 0);  // the resumed steps reused factors
}

TEST(TimeResume, TheCoupledRunContinuesBitForBit) {
  const auto s = run_stop_resume(
      "resume-coupled",
      "run " + kCases + "paper-7.2-dynamic.toml' --set fluid.h=0.03 --set structure.h=0.03 --set time.dt=0.02 "
      "--set time.t_end=0.12 --set time.output_every=2 --set output.png=false --set coupling.scheme=iqn-ils "
      "--set coupling.reuse=4 --set coupling.tol=1e-4",
      3, 3);
  EXPECT_EQ(s["steps"], 6);
  EXPECT_EQ(s["status"], "converged");
}

// A resumed run may go further than the first: a later time.t_end.
TEST(TimeResume, ARunExtendsToALaterEnd) {
  const fs::path dir = testing::scratch_dir("resume-extend");
  const std::string bar = "run " + kCases +
                          "bar-impact.toml' --set structure.h=0.02 --set time.dt=1e-3 -q --set output.png=false "
                          "--set output.vtu=false";
  ASSERT_EQ(testing::run_cli(bar + " --set time.t_end=0.1 --out a", dir).status, 0);
  const testing::CliRun more = testing::run_cli(bar + " --set time.t_end=0.15 --resume a", dir);
  ASSERT_EQ(more.status, 0) << more.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "a/summary.json"));
  EXPECT_EQ(s["steps"], 150);
  EXPECT_EQ(s["resumed"]["step"], 100);
  ASSERT_EQ(testing::run_cli(bar + " --set time.t_end=0.15 --out whole", dir).status, 0);
  EXPECT_TRUE(bytes(dir / "a/history.csv") == bytes(dir / "whole/history.csv"));
}

// --resume from what is no checkpoint of this case: exit 2, naming the file and what
// differs, and the directory left as it was.
TEST(TimeResume, RefusesWhatIsNoCheckpointOfTheCase) {
  const fs::path dir = testing::scratch_dir("resume-refusals");
  const std::string bar = "run " + kCases + "bar-impact.toml' --set structure.h=0.02 --set time.dt=1e-3 -q";
  ASSERT_EQ(testing::run_cli(bar + " --set time.t_end=0.05 --out a", dir).status, 0);
  const std::string before = bytes(dir / "a/summary.json");
  const struct {
    std::string args, says;
  } refusals[] = {
      {bar + " --set time.t_end=0.05 --resume nowhere", "not a directory"},
      {bar + " --set time.t_end=0.05 --set structure.E=200 --resume a", "another case"},
      {bar + " --set time.t_end=0.02 --resume a", "past time.t_end"},
      {bar + " --set time.t_end=0.05 --resume a --out elsewhere", "--out elsewhere"},
      {"run " + kCases + "paper-7.2.toml' -q --resume a", "no [time] section"},
  };
  for (const auto& r : refusals) {
    const testing::CliRun run = testing::run_cli(r.args, dir);
    EXPECT_EQ(run.status, 2) << r.args << "\n" << run.err;
    EXPECT_NE(run.err.find(r.says), std::string::npos) << r.args << "\n" << run.err;
  }
  EXPECT_FALSE(fs::exists(dir / "elsewhere"));
  EXPECT_EQ(bytes(dir / "a/summary.json"), before);
  // A damaged checkpoint: truncated, then one byte altered.
  std::string k = bytes(dir / "a/checkpoint.bin");
  std::ofstream(dir / "a/checkpoint.bin", std::ios::binary) << k.substr(0, k.size() - 9);
  testing::CliRun run = testing::run_cli(bar + " --set time.t_end=0.05 --resume a", dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("truncated"), std::string::npos) << run.err;
  k[k.size() - 20] ^= 1;
  std::ofstream(dir / "a/checkpoint.bin", std::ios::binary) << k;
  run = testing::run_cli(bar + " --set time.t_end=0.05 --resume a", dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("checksum"), std::string::npos) << run.err;
  std::ofstream(dir / "a/checkpoint.bin") << "[structure]\nE = 1\n";
  run = testing::run_cli(bar + " --set time.t_end=0.05 --resume a", dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("not a checkpoint of fsicontact"), std::string::npos) << run.err;
  EXPECT_EQ(bytes(dir / "a/summary.json"), before);
}

}  // namespace
}  // namespace fsi::time_resume_test
