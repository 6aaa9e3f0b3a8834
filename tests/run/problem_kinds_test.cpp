// One pipeline (run/problem.hpp, run/problem_kinds.hpp): the kind of run is a type chosen once from the case,
// and each kind writes what its summary says it is. A P2 structure coupled to the
// penalised fluid runs to convergence (the fluid is sampled at its P2 nodes: a
// sampling mesh of the P1 vertices made every P2 coupled run fail before).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "io/case.hpp"
#include "run/problem_kinds.hpp"
#include "run/run_case.hpp"

namespace fsi::problem_kinds_test {
namespace {

namespace fs = std::filesystem;

Case paper(std::vector<std::string> sets, const std::string& out) {
  sets.insert(sets.begin(), {"fluid.h=0.02", "structure.h=0.03", "output.png=false", "output.vtu=false"});
  Case c = load_case("", sets);
  c.output.dir = (fs::temp_directory_path() / ("fsicontact-kinds-" + out + "-" + std::to_string(::getpid()))).string();
  return c;
}

TEST(Problem, TheKindIsChosenOnceFromTheCase) {
  const RunOptions options;
  const Case contact = load_case(std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.1-fig5-coarse.toml");
  EXPECT_STREQ(make_problem(contact, options)->kind(), "contact");
  EXPECT_STREQ(make_problem(paper({"structure.shape=none"}, "none"), options)->kind(), "fluid");
  EXPECT_STREQ(make_problem(paper({"coupling.max_iterations=0"}, "rest"), options)->kind(), "fluid");
  EXPECT_STREQ(
      make_problem(paper({"coupling.max_iterations=0", "fluid.method=body-fitted", "obstacle.y0=-0.2"}, "bf"), options)
          ->kind(),
      "fluid");
  EXPECT_STREQ(make_problem(paper({}, "fsi"), options)->kind(), "fsi");
}

TEST(Problem, TheFluidAroundTheStructureAtRestSaysSo) {
  const Case c = paper({"coupling.max_iterations=0"}, "at-rest");
  const RunResult r = run_case(c, {});
  ASSERT_EQ(r.exit_status, 0) << r.failure;
  EXPECT_EQ(r.summary["problem"], "fluid");
  EXPECT_FALSE(r.summary.contains("contact"));  // the structure is not solved
  EXPECT_TRUE(fs::exists(fs::path(c.output.dir) / "summary.json"));
  EXPECT_FALSE(fs::exists(fs::path(c.output.dir) / "history.csv"));  // no loop ran
  fs::remove_all(c.output.dir);
}

TEST(Problem, AP2StructureCouplesToThePenalisedFluid) {
  // The paper's meshes (at hF = 0.02, hS = 0.03 the P2 run's χ flickers between two
  // sets and the increment stalls at 2.6e-4 > tol: the penalised fixed point's limit
  // cycle on coarse meshes, not this seam).
  const std::vector<std::string> paper_h{"fluid.h=0.01", "structure.h=0.015"};
  const Case p1 = paper(paper_h, "p1");
  std::vector<std::string> with_p2 = paper_h;
  with_p2.push_back("structure.element=P2");
  const Case p2 = paper(with_p2, "p2");
  const RunResult r1 = run_case(p1, {}), r2 = run_case(p2, {});
  ASSERT_EQ(r1.exit_status, 0) << r1.failure;
  ASSERT_EQ(r2.exit_status, 0) << r2.failure;
  EXPECT_EQ(r2.summary["problem"], "fsi");
  // Both press the beam onto the disk, which holds the largest displacement: measured
  // 37.97 mm (P1) and 40.99 mm (P2, 8 % more: the stiffer P1 beam at hS = 0.015).
  const double u1 = r1.measures.displacement->max, u2 = r2.measures.displacement->max;
  EXPECT_GT(u2, u1) << "P1 " << u1 << " m, P2 " << u2 << " m";
  EXPECT_LT(u2, 1.15 * u1) << "P1 " << u1 << " m, P2 " << u2 << " m";
  fs::remove_all(p1.output.dir);
  fs::remove_all(p2.output.dir);
}

}  // namespace
}  // namespace fsi::problem_kinds_test
