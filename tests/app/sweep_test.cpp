// The sweep against careless rows files (issue 11, class 9), end to end: the whole
// CSV, every row's case and meshes are validated before anything is written; its
// exit status says whether every row converged; a row's solver options are its own.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::sweep_test {
namespace {

namespace fs = std::filesystem;

const std::string kBase = std::string("'") + FSICONTACT_SOURCE_DIR + "/cases/paper-7.2.toml'";
const std::string kCoarse = " --set fluid.h=0.02 --set structure.h=0.03";

struct BadRows {
  std::string label, csv;
  std::vector<std::string> expected;
};

void PrintTo(const BadRows& b, std::ostream* os) { *os << b.label; }

class BadRowsTest : public ::testing::TestWithParam<BadRows> {};

// Exit status 2, one line naming the file and what is wrong, nothing written.
TEST_P(BadRowsTest, IsRejectedBeforeAnyRowRuns) {
  const BadRows& b = GetParam();
  const fs::path dir = testing::scratch_dir("sweep-" + b.label);
  testing::write_text(dir / "rows.csv", b.csv);
  const testing::CliRun r = testing::run_cli("sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  for (const auto& s : b.expected) EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "tab")) << "a row ran or a file was written";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadRowsTest,
    ::testing::Values(
        BadRows{"header_only", "coupling.eps,coupling.omega\n", {"rows.csv", "a header and no rows"}},
        BadRows{"empty", "# nothing\n\n", {"rows.csv", "empty rows file"}},
        BadRows{"unknown_column_with_empty_cells", "coupling.eps,coupling.omgea\n1e-4,\n", {"column 2", "coupling.omgea", "not a case key"}},
        BadRows{"duplicate_column", "coupling.eps,coupling.omega,coupling.eps\n1e-4,0.1,1e-5\n", {"column 3", "appears twice"}},
        BadRows{"output_dir_column", "coupling.eps,output.dir\n1e-4,elsewhere\n", {"column 2", "output.dir", "row-NN"}},
        BadRows{"unnamed_column", "coupling.eps,,paper.k\n1e-4,1,2\n", {"column 2", "no name"}},
        BadRows{"open_quote", "coupling.eps,coupling.scheme\n1e-4,\"aitken\n", {"rows.csv:2", "quote"}},
        BadRows{"bad_value_in_row_2", "coupling.eps,coupling.omega\n1e-4,0.1\n1e-5,7\n", {"rows.csv: row 2", "coupling.omega"}},
        BadRows{"missing_mesh_in_row_2", "coupling.eps,fluid.mesh\n1e-4,\n1e-5,nowhere.msh\n", {"rows.csv: row 2", "fluid.mesh", "nowhere.msh"}}),
    [](const auto& param_info) { return param_info.param.label; });

// Rows that reach their iteration limit make the sweep's exit status 3 (as a run's);
// each row is marked, and the sweep's summary.json says how each ended.
TEST(Sweep, RowsAtTheirLimitGiveExitStatus3) {
  const fs::path dir = testing::scratch_dir("sweep-limit");
  testing::write_text(dir / "rows.csv", "label,coupling.max_iterations\nfull,100\n\"two, only\",2\n");
  const testing::CliRun r = testing::run_cli("sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir);
  EXPECT_EQ(r.status, 3) << r.err;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "tab/summary.json"));
  EXPECT_EQ(j["status"], "complete");
  EXPECT_EQ(j["converged"], 1);
  EXPECT_EQ(j["not_converged"], 1);
  EXPECT_EQ(j["row_status"][1], "not converged");
  fs::remove_all(dir);
}

// A failing row is recorded (its summary.json "failed"), the others still run, and
// the sweep exits 1.
TEST(Sweep, AFailedRowIsRecordedAndGivesExitStatus1) {
  const fs::path dir = testing::scratch_dir("sweep-failed");
  testing::write_text(dir / "rows.csv", "coupling.eps\n1e-4\n1e-5\n");
  const testing::CliRun r = testing::run_shell(
      "FSICONTACT_FAULT=fluid '" + std::string(FSICONTACT_BINARY) + "' sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir);
  EXPECT_EQ(r.status, 1) << r.err;
  for (const char* row : {"row-01", "row-02"})
    EXPECT_EQ(nlohmann::json::parse(testing::slurp(dir / "tab" / row / "summary.json"))["status"], "failed") << row;
  EXPECT_NE(testing::slurp(dir / "tab/table.md").find("failed: injected fault"), std::string::npos);
  fs::remove_all(dir);
}

// The setup cache used to ignore fluid.factorization and fluid.keep_far_factors_mb:
// a row ran with the previous row's solver. Each row's summary now reports its own.
TEST(Sweep, EveryRowRunsWithItsOwnSolverOptions) {
  const fs::path dir = testing::scratch_dir("sweep-solver");
  testing::write_text(dir / "rows.csv", "fluid.factorization,fluid.keep_far_factors_mb\nschur,128\nwhole,128\nschur,0\n");
  ASSERT_EQ(testing::run_cli("sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir).status, 0);
  const char* expected[] = {"schur", "whole", "schur"};
  for (int i = 0; i < 3; ++i) {
    const auto j = nlohmann::json::parse(testing::slurp(dir / "tab" / ("row-0" + std::to_string(i + 1)) / "summary.json"));
    EXPECT_EQ(j["fluid"]["factorization"], expected[i]) << "row " << i + 1;
    EXPECT_EQ(j["parameters"]["fluid"]["factorization"], expected[i]) << "row " << i + 1;
    EXPECT_TRUE(j["parameters"]["fluid"].contains("keep_far_factors_mb"));
  }
  fs::remove_all(dir);
}

// A rerun with fewer rows into the same directory: the earlier sweep's extra row
// directories go (a user's own file in one stays, with its directory).
TEST(Sweep, ARerunWithFewerRowsLeavesNoStaleRows) {
  const fs::path dir = testing::scratch_dir("sweep-stale");
  testing::write_text(dir / "rows.csv", "coupling.eps\n1e-4\n1e-5\n1e-3\n");
  ASSERT_EQ(testing::run_cli("sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir).status, 0);
  testing::write_text(dir / "tab/row-02/mine.txt", "keep");
  testing::write_text(dir / "rows.csv", "coupling.eps\n1e-4\n");
  ASSERT_EQ(testing::run_cli("sweep " + kBase + " rows.csv --out tab -q" + kCoarse, dir).status, 0);
  EXPECT_FALSE(fs::exists(dir / "tab/row-03"));
  EXPECT_TRUE(fs::exists(dir / "tab/row-02/mine.txt"));
  EXPECT_FALSE(fs::exists(dir / "tab/row-02/summary.json"));
  const std::string csv = testing::slurp(dir / "tab/table.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::sweep_test
