// Two runs of the same case give bit-identical results (timings aside), whether the
// libraries may use 1 or 2 threads: summary.json numbers and .vtu files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>

#include "support/cli.hpp"

namespace fsi::reproducibility_test {
namespace {

namespace fs = std::filesystem;

// Every key ending in "_s" is a wall time (timing_s, fluid.solve_s, ...): drop them all,
// at any depth, so that a timing added later cannot make this test fail.
void drop_timings(nlohmann::json& j) {
  if (!j.is_object()) return;
  for (auto it = j.begin(); it != j.end();) {
    const std::string& k = it.key();
    if (k.size() > 2 && k.compare(k.size() - 2, 2, "_s") == 0) {
      it = j.erase(it);
    } else {
      drop_timings(*it);
      ++it;
    }
  }
}

nlohmann::json without_timings(nlohmann::json j) {
  drop_timings(j);
  j["parameters"]["output"].erase("dir");
  return j;
}

TEST(Reproducibility, RunsAreBitIdenticalWithOneOrTwoThreads) {
  const fs::path dir = testing::scratch_dir("repro");
  const std::string args = "run --set fluid.h=0.02 --set structure.h=0.03 --set coupling.scheme=iqn-ils -q";
  const testing::CliRun a = testing::run_shell("env OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 '" +
                                                 std::string(FSICONTACT_BINARY) + "' " + args + " --out a", dir);
  const testing::CliRun b = testing::run_shell("env OMP_NUM_THREADS=2 OPENBLAS_NUM_THREADS=2 '" +
                                                 std::string(FSICONTACT_BINARY) + "' " + args + " --out b", dir);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ja = without_timings(nlohmann::json::parse(testing::slurp(dir / "a/summary.json")));
  const auto jb = without_timings(nlohmann::json::parse(testing::slurp(dir / "b/summary.json")));
  EXPECT_EQ(ja.dump(), jb.dump());
  for (const char* f : {"fluid.vtu", "structure.vtu", "history.csv"}) {
    std::string ta = testing::slurp(dir / "a" / f), tb = testing::slurp(dir / "b" / f);
    if (std::string(f) == "history.csv") {  // the time columns differ; keep the first six
      auto strip = [](const std::string& t) {
        std::string out, line;
        std::istringstream in(t);
        while (std::getline(in, line)) {
          std::size_t pos = 0;
          for (int k = 0; k < 6 && pos != std::string::npos; ++k) pos = line.find(',', pos + 1);
          out += line.substr(0, pos) + "\n";
        }
        return out;
      };
      ta = strip(ta), tb = strip(tb);
    }
    EXPECT_FALSE(ta.empty()) << f;
    EXPECT_TRUE(ta == tb) << f << " differs between the runs";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::reproducibility_test
