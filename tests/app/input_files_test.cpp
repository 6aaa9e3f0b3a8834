// What a newcomer gives as input that is not what it seems (issue 31's small defects):
// a case "file" that exists but is no regular file (a FIFO here; a directory and
// /dev/zero are in bad_input_test's table) is named for what it is, exit 2, without
// blocking on the pipe; and `obstacles = []`, where no contact can happen, runs with
// the default contact keys.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::input_files_test {
namespace {

namespace fs = std::filesystem;

TEST(InputFiles, AFifoAsTheCaseFileIsNamedForWhatItIs) {
  const fs::path dir = testing::scratch_dir("input-fifo");
  ASSERT_EQ(mkfifo((dir / "pipe.toml").c_str(), 0600), 0);
  const testing::CliRun r = testing::run_cli("run pipe.toml --out result", dir);  // must not wait for a writer
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("pipe.toml: a FIFO (named pipe), not a case file; expected a regular TOML file"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "result"));
  fs::remove_all(dir);
}

// No obstacle: the paper's gap (eq. 15, one disk's graph) and Gamma_C (that disk's
// span) have nothing to refer to, and nothing to do; they resolve to what needs no
// obstacle, and the beam bends under its load alone.
TEST(InputFiles, NoObstacleRunsWithTheDefaultContactKeys) {
  const fs::path dir = testing::scratch_dir("input-no-obstacle");
  testing::write_text(dir / "case.toml", "name = \"free\"\nobstacles = []\n[structure]\nh = 0.03\n");
  const testing::CliRun r =
      testing::run_cli("run case.toml -q --out res --set output.png=false --set output.vtu=false", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  EXPECT_EQ(s["parameters"]["contact"]["gap"], "normal");
  EXPECT_EQ(s["parameters"]["contact"]["boundary"], "all");
  EXPECT_EQ(s["contact"]["active_nodes"], 0);
  EXPECT_GT(s["max_displacement"].get<double>(), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::input_files_test
