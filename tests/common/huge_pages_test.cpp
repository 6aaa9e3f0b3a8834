// The allocator's huge pages (common/huge_pages.hpp): when the program starts itself
// again with glibc's tunable, and that a run's numbers do not depend on it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/huge_pages.hpp"
#include "support/cli.hpp"

namespace fsi::huge_pages_test {
namespace {

namespace fs = std::filesystem;

TEST(HugePages, RestartOnlyWhereTheUserLeftTheTunableAloneAndTheKernelWaitsForAdvice) {
  const std::string advised = "always [madvise] never\n";
  EXPECT_TRUE(wants_huge_page_restart(nullptr, advised));
  EXPECT_FALSE(wants_huge_page_restart("", advised)) << "set, even empty: the user's choice";
  EXPECT_FALSE(wants_huge_page_restart("glibc.malloc.hugetlb=1", advised)) << "restarted already";
  EXPECT_FALSE(wants_huge_page_restart("glibc.malloc.arena_max=2", advised));
  EXPECT_FALSE(wants_huge_page_restart(nullptr, "[always] madvise never\n")) << "huge pages anyway";
  EXPECT_FALSE(wants_huge_page_restart(nullptr, "always madvise [never]\n"));
  EXPECT_FALSE(wants_huge_page_restart(nullptr, "")) << "no such file";
}

nlohmann::json run_summary(const std::string& env, const fs::path& dir, const std::string& out) {
  const testing::CliRun r = testing::run_shell(
      env + " '" + FSICONTACT_BINARY + "' run --set fluid.h=0.02 --set structure.h=0.03 -q --out " + out, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(testing::slurp(dir / out / "summary.json"));
}

// summary.json's program.huge_pages says what the run had; the numbers are the same
// (timings aside) with the allocator's huge pages and without.
TEST(HugePages, ARunSaysWhetherItHadThemAndGivesTheSameNumbersEither) {
  const fs::path dir = testing::scratch_dir("huge-pages");
  const nlohmann::json on = run_summary("env -u GLIBC_TUNABLES", dir, "on");
  const nlohmann::json off = run_summary("env GLIBC_TUNABLES=", dir, "off");
  const std::string mode = thp_mode();
  const bool always = mode.find("[always]") != std::string::npos;
  const bool restarts = !sanitized_allocator();  // as restart_with_huge_pages decides
  EXPECT_EQ(on["program"]["huge_pages"], always || (restarts && mode.find("[madvise]") != std::string::npos)) << mode;
  EXPECT_EQ(off["program"]["huge_pages"], always) << mode;
  EXPECT_EQ(on["max_displacement"], off["max_displacement"]);
  EXPECT_EQ(on["iterations"], off["iterations"]);
  EXPECT_EQ(on["final_increment_l2"], off["final_increment_l2"]);
  EXPECT_EQ(on["fluid_velocity_l2_in_structure"], off["fluid_velocity_l2_in_structure"]);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::huge_pages_test
