// The run directory's life (summary.json first as "writing", stale files of an
// earlier run removed, failed writes recorded) and the rows file's CSV.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "run/csv.hpp"
#include "run/outputs/output_dir.hpp"

namespace fsi::outputs_and_rows_test {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("fsicontact-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(RunOutputs, BeginMarksTheDirectoryAndClearsAnEarlierRun) {
  const fs::path dir = fresh("outputs");
  fs::create_directories(dir);
  for (const char* old : {"fsi.png", "history.csv", "summary.json", "fluid.vtu.tmp12", "notes.txt", "fsi.png.tmpx"})
    std::ofstream(dir / old) << "old";
  RunOutputs out(dir.string());
  out.begin({{"name", "t"}});
  EXPECT_EQ(Json::parse(slurp(dir / "summary.json"))["status"], "writing");
  for (const char* gone : {"fsi.png", "history.csv", "fluid.vtu.tmp12"}) EXPECT_FALSE(fs::exists(dir / gone)) << gone;
  for (const char* kept : {"notes.txt", "fsi.png.tmpx"}) EXPECT_TRUE(fs::exists(dir / kept)) << kept;  // not ours
  EXPECT_TRUE(out.write("case.toml", [](const std::string& p) { std::ofstream(p) << "x"; }));
  EXPECT_FALSE(out.write("fluid.vtu", [](const std::string& p) { throw OutputError(p, ENOSPC); }));
  const Json final = out.finish({{"name", "t"}, {"status", "converged"}});
  EXPECT_EQ(final["status"], "failed");
  EXPECT_EQ(final["solve_status"], "converged");
  EXPECT_NE(final["failure"].get<std::string>().find("fluid.vtu: No space left on device"), std::string::npos);
  EXPECT_EQ(Json::parse(slurp(dir / "summary.json")), final);
  fs::remove_all(dir);
}

TEST(RunOutputs, BeginFailsWithThePathAndTheReason) {
  const fs::path dir = fresh("outputs-file");
  std::ofstream(dir.string()) << "a file";
  RunOutputs out((dir / "sub").string());
  try {
    out.begin({});
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
  fs::remove(dir);
}

TEST(Csv, QuotesCommasAndDoubledQuotes) {
  const fs::path dir = fresh("csv");
  fs::create_directories(dir);
  std::ofstream(dir / "rows.csv") << "# comment\n\na, b ,c\n\"x, y\",\"say \"\"hi\"\"\", z \n1,,3\n";
  const CsvTable t = read_csv((dir / "rows.csv").string());
  ASSERT_EQ(t.header, (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"x, y", "say \"hi\"", "z"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"1", "", "3"}));
  EXPECT_EQ(t.line_of_row, (std::vector<int>{4, 5}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::outputs_and_rows_test
