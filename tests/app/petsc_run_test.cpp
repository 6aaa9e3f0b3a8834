// fluid.linear_solver through the program (SPEC §13): the §7.2 case's answer on each
// solver, summary.json's linear_solver, linear_iterations and ranks; what runs on one
// rank only refused on several, nothing written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fsi::petsc_run_test {
namespace {

using nlohmann::json;
using testing::run_cli;
using testing::run_shell;
using testing::scratch_dir;
using testing::slurp;

// The §7.2 case on its coarse fluid (hF = 0.02), no figures.
json run_with(const std::string& solver, const std::filesystem::path& dir, const std::string& krylov = "gmres") {
  const std::string out = solver + "-" + krylov;
  const testing::CliRun r = run_cli("run -q --set fluid.h=0.02 --set output.png=false --set output.vtu=false "
                                    "--set fluid.linear_solver='\"" + solver + "\"' --set fluid.krylov=" + krylov +
                                        " --out " + out, dir);
  EXPECT_EQ(r.status, 0) << solver << ": " << r.err;
  return json::parse(slurp(dir / out / "summary.json"));
}

TEST(PetscRun, EverySolverGivesTheDirectAnswer) {
#ifndef FSICONTACT_HAVE_PETSC
  GTEST_SKIP() << "built without PETSc";
#endif
  const auto dir = scratch_dir("petsc-run");
  const json mumps = run_with("mumps", dir);
  EXPECT_EQ(mumps["fluid"]["linear_solver"], "mumps");
  EXPECT_EQ(mumps["ranks"], 1);
  json iterative;
  for (const char* solver : {"petsc-mumps", "petsc-iterative"}) {
    const json s = run_with(solver, dir);
    EXPECT_EQ(s["fluid"]["linear_solver"], solver);
    EXPECT_EQ(s["fluid"]["factorization"], "whole");
    EXPECT_EQ(s["iterations"], mumps["iterations"]) << solver;
    EXPECT_NEAR(s["max_displacement"].get<double>(), mumps["max_displacement"].get<double>(), 1e-9) << solver;
    if (std::string(solver) == "petsc-iterative") iterative = s;
  }
  const json bicgstab = run_with("petsc-iterative", dir, "bicgstab");
  EXPECT_EQ(bicgstab["fluid"]["krylov"], "bicgstab");
  EXPECT_EQ(bicgstab["iterations"], mumps["iterations"]);
  EXPECT_NEAR(bicgstab["max_displacement"].get<double>(), mumps["max_displacement"].get<double>(), 1e-9);
  // One count per solve (a pass whose χ did not change reuses the last solution).
  ASSERT_TRUE(iterative["fluid"].contains("linear_iterations"));
  EXPECT_EQ(iterative["fluid"]["linear_iterations"].size(), iterative["fluid"]["factorizations"].get<std::size_t>());
  EXPECT_GT(iterative["fluid"]["linear_iterations_total"].get<long>(), 0);
  std::filesystem::remove_all(dir);
}

// On several ranks (the launcher's environment, here without one) the sequential
// solver and --resume are refused, exit 2, nothing written. Runs on two ranks are
// tests/mpi/two_ranks.sh's (ctest Mpi.*).
TEST(PetscRun, WhatRunsOnOneRankIsRefusedOnSeveralWithNothingWritten) {
  const auto dir = scratch_dir("petsc-ranks");
  const std::string program = std::string("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 '") + FSICONTACT_BINARY + "'";
  testing::CliRun r = run_shell(program + " run -q --out res", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("fluid.linear_solver = \"mumps\" runs on one rank; this run has 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("petsc-mumps"), std::string::npos) << r.err;
  r = run_shell(program + " run -q --resume res", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--resume runs on one rank; this run has 2"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "res"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fsi::petsc_run_test
