// fluid.linear_solver = "petsc-mumps" and "petsc-iterative" (SPEC §13) against the
// sequential MUMPS the program calls directly: the same solution, to the solver's
// tolerance, for a penalty 1/ε from 1e2 to 1e7, for Stokes (symmetric) and Newton's
// Navier–Stokes Jacobian (unsymmetric); an iteration limit reached is a failure with
// its residual history. Without the PETSc plugin (the instrumented build:
// cmake/Dependencies.cmake) asking for it is a SolverFailure naming the package.
#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <limits>
#include <numeric>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/launch.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fluid/petsc_solver.hpp"
#include "fluid/stokes_strategy.hpp"
#include "support/norms.hpp"
#include "support/stokes_mms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::petsc_solver_test {
namespace {

// The lid-driven cavity (0,1)², 16×16 cells, a penalised block in the middle; the right
// side traction-free.
struct Cavity {
  explicit Cavity(int cells = 16) : mesh(testing::structured_rectangle(1.0, 1.0, cells, cells)) {}
  Mesh mesh;
  Eigen::VectorXd chi() const {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(mesh.num_triangles());
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      Point centre = Point::Zero();
      for (int v : mesh.triangles[t]) centre += mesh.vertices[v] / 3.0;
      if (centre.x() > 0.35 && centre.x() < 0.65 && centre.y() > 0.3 && centre.y() < 0.5) c[t] = 1.0;
    }
    return c;
  }
  FluidBoundaryConditions bc() const {
    FluidBoundaryConditions bc;
    for (const char* name : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(name));
    bc.g = [](const Point& x) { return x.y() > 1 - 1e-12 ? Point(x.x() * (1 - x.x()), 0) : Point(0, 0); };
    return bc;
  }
  static Point gravity(const Point&) { return Point(0, -9.81); }
  std::unique_ptr<PenalisedStokes> stokes(double eps, const std::string& solver = kDefaultSparseSolver) const {
    auto s = std::make_unique<PenalisedStokes>(mesh, 0.01, eps, gravity, bc(), solver);
    s->set_chi(chi());
    return s;
  }
};

// The solver's options, allowing the few unknowns a rank of these small problems when
// this test runs on two ranks (ctest Mpi.PetscSolversOnTwoRanks).
LinearSolverOptions small(double tol, int max_iterations, const char* krylov = "gmres") {
  LinearSolverOptions options(tol, max_iterations, krylov);
  options.min_unknowns_per_rank = 1;
  return options;
}

bool have_petsc() {
#ifdef FSICONTACT_HAVE_PETSC
  return true;
#else
  return false;
#endif
}

// The relative difference of the velocities and of the pressures.
void expect_close(const FluidSolution& a, const FluidSolution& b, double tol, const std::string& what) {
  Eigen::VectorXd va(2 * a.v1.size()), vb(2 * b.v1.size());
  va << a.v1, a.v2;
  vb << b.v1, b.v2;
  EXPECT_LE((va - vb).norm(), tol * vb.norm()) << what << ": velocity";
  EXPECT_LE((a.p - b.p).norm(), tol * b.p.norm()) << what << ": pressure";
}

TEST(PetscSolver, MumpsThroughPetscEqualsMumpsFromEps1e2To1e7) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  for (double eps : {1e-2, 1e-5, 1e-7}) {
    auto direct = cavity.stokes(eps), petsc = cavity.stokes(eps);
    petsc->set_linear_solver("petsc-mumps", small(1e-10, 1000));
    const FluidSolution expected = direct->solve();
    expect_close(petsc->solve(), expected, 1e-10, "petsc-mumps, ε = " + std::to_string(eps));
    EXPECT_EQ(petsc->solver_name(), "petsc-mumps");
    EXPECT_TRUE(petsc->timing().linear_iterations.empty());  // a direct solver
  }
}

// Each rank assembles only the rows PETSc gives it (StokesAssembler::share_rows): on
// two ranks (ctest Mpi.PetscSolversOnTwoRanks) a rank's K holds fewer entries than
// the whole, the ranks' entries and right-hand sides add up to the whole system's,
// and the solution is the direct path's; on one rank it holds them all.
TEST(PetscSolver, EachRankAssemblesOnlyItsOwnRows) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  const double eps = 1e-5;
  const FluidSolution expected = cavity.stokes(eps)->solve();
  StokesAssembler whole_system(cavity.mesh, 0.01, Cavity::gravity, cavity.bc());
  whole_system.assemble(cavity.chi(), eps);
  for (const std::string solver : {"petsc-mumps", "petsc-iterative"}) {
    StokesAssembler assembler(cavity.mesh, 0.01, Cavity::gravity, cavity.bc());
    FluidTiming timing;
    FluidSolution out;
    WholeSolve whole(assembler, solver, timing, out, small(1e-11, 500));
    whole.solve(cavity.chi(), eps, nullptr);
    if (solver == "petsc-iterative") {  // it holds K's blocks: K freed, built anew by the next assembly
      EXPECT_EQ(assembler.matrix().nonZeros(), 0) << solver;
      assembler.assemble(cavity.chi(), eps);
    }
    // Σ over the ranks of a number: the square of the norm of its square root.
    const auto summed = [&whole](double x) { return std::pow(whole.norm(Eigen::VectorXd::Constant(1, std::sqrt(x))), 2); };
    const double ranks = summed(1.0), held = static_cast<double>(assembler.matrix().nonZeros());
    EXPECT_NEAR(summed(held), static_cast<double>(whole_system.matrix().nonZeros()), 0.5) << solver;
    if (ranks > 1.5) EXPECT_LT(held, 0.75 * static_cast<double>(whole_system.matrix().nonZeros())) << solver;
    else EXPECT_EQ(held, static_cast<double>(whole_system.matrix().nonZeros())) << solver;
    EXPECT_NEAR(whole.norm(assembler.rhs()), whole_system.rhs().norm(), 1e-12 * whole_system.rhs().norm()) << solver;
    expect_close(out, expected, solver == "petsc-mumps" ? 1e-10 : 1e-7, solver);
  }
}

// The iterative solver to 1e-10 relative residual, with either Krylov method
// (fluid.krylov): the solution to ~1e-8, with as many iterations at ε = 1e-7 as at
// 1e-2 within a factor (the preconditioner follows the penalty: petsc_plugin.cpp).
TEST(PetscSolver, IterativeAgreesWithMumpsFromEps1e2To1e7InBoundedIterations) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  for (const char* krylov : {"gmres", "bicgstab"}) {
    std::vector<int> iterations;
    for (double eps : {1e-2, 1e-5, 1e-7}) {
      auto direct = cavity.stokes(eps), petsc = cavity.stokes(eps);
      petsc->set_linear_solver("petsc-iterative", small(1e-10, 500, krylov));
      const FluidSolution expected = direct->solve();
      expect_close(petsc->solve(), expected, 1e-7, std::string(krylov) + ", ε = " + std::to_string(eps));
      ASSERT_EQ(petsc->timing().linear_iterations.size(), 1u);
      iterations.push_back(petsc->timing().linear_iterations[0]);
      std::printf("%s, ε = %g: %d iterations\n", krylov, eps, iterations.back());
    }
    EXPECT_GT(iterations.front(), 1) << krylov;
    EXPECT_LE(iterations.back(), 3 * iterations.front() + 10) << krylov;
  }
}

// The preconditioner's quality does not decay with h: GMRES's iterations on the cavity
// at 16, 32 and 64 cells a side within a factor 1.5 (1.5 s: a unit test, as the only
// one to run the split without the mass).
// Without the fluid's pressure mass in the Schur preconditioner (PETSc's selfp alone)
// they grow: more iterations on the finest mesh.
TEST(PetscSolver, IterationsStayFlatAsTheMeshIsRefined) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  std::vector<int> iterations, selfp;
  for (int cells : {16, 32, 64}) {
    const Cavity cavity(cells);
    for (bool mass : {true, false}) {
      auto petsc = cavity.stokes(1e-5);
      LinearSolverOptions options = small(1e-10, 1000);
      options.schur_mass = mass;
      petsc->set_linear_solver("petsc-iterative", options);
      petsc->solve();
      (mass ? iterations : selfp).push_back(petsc->timing().linear_iterations.at(0));
    }
    std::printf("%d cells a side: %d iterations (selfp alone: %d)\n", cells, iterations.back(), selfp.back());
  }
  const auto [low, high] = std::minmax_element(iterations.begin(), iterations.end());
  EXPECT_LE(*high, 1.5 * *low);
  EXPECT_GT(selfp.back(), iterations.back());
}

// A second solve with a changed χ starts from the first's solution.
TEST(PetscSolver, IterativeStartsFromTheLastSolution) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  auto petsc = cavity.stokes(1e-5), direct = cavity.stokes(1e-5);
  petsc->set_linear_solver("petsc-iterative", small(1e-10, 500));
  petsc->solve();
  Eigen::VectorXd chi = cavity.chi();
  chi[0] = 1.0;  // one triangle more: a nearby problem
  petsc->set_chi(chi);
  direct->set_chi(chi);
  expect_close(petsc->solve(), direct->solve(), 1e-7, "second solve");
  const std::vector<int>& n = petsc->timing().linear_iterations;
  ASSERT_EQ(n.size(), 2u);
  EXPECT_LT(n[1], n[0]);
}

TEST(PetscSolver, AnIterationLimitIsAFailureWithTheResidualHistory) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  for (const char* krylov : {"gmres", "bicgstab"}) {
    auto petsc = cavity.stokes(1e-5);
    petsc->set_linear_solver("petsc-iterative", small(1e-12, 2, krylov));
    try {
      petsc->solve();
      ADD_FAILURE() << krylov << ": two iterations reached 1e-12";
    } catch (const SolverFailure& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("did not converge"), std::string::npos) << what;
      EXPECT_NE(what.find("relative residuals"), std::string::npos) << what;
      EXPECT_NE(what.find("fluid.linear_max_iterations = 2"), std::string::npos) << what;
      EXPECT_NE(what.find("fluid.krylov = \"" + std::string(krylov) + "\""), std::string::npos) << what;
    }
    EXPECT_EQ(petsc->timing().linear_iterations, std::vector<int>{2}) << krylov;
  }
}

// Newton's Jacobian of Navier–Stokes is unsymmetric: MUMPS's LU through PETSc gives
// Newton's answer of the direct path. (The iterative solver is refused for it, by the
// case reader: its Schur approximation ignores the convection, and GMRES broke down or
// took 150–500 iterations here, measured with PETSC_OPTIONS.)
TEST(PetscSolver, NavierStokesThroughPetscEqualsTheDirectPath) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const Cavity cavity;
  const auto navier_stokes = [&](const std::string& solver) {
    auto s = cavity.stokes(1e-4, kNavierStokesSolver);
    if (solver != kNavierStokesSolver) s->set_linear_solver(solver, small(1e-11, 500));
    s->set_navier_stokes({1.0, 1e-10, 30, false});  // Re = ρ U L / μ = 25
    return s;
  };
  auto direct = navier_stokes(kNavierStokesSolver);
  const FluidSolution expected = direct->solve();
  auto petsc = navier_stokes("petsc-mumps");
  expect_close(petsc->solve(), expected, 1e-9, "petsc-mumps");
  EXPECT_GE(petsc->newton()->steps, 2);
}

// The manufactured Stokes solution (support/stokes_mms.hpp) through each PETSc solver
// on 16, 32 and 64 cells a side: the errors of the direct path's to 1e-6 of
// themselves, so the mini element's rates (velocity 2 in L², 1 in H¹, pressure at
// least 1), checked again. On two ranks too (ctest Mpi.PetscSolversOnTwoRanks).
TEST(PetscSolver, ManufacturedStokesKeepsTheMiniElementsRates) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const std::vector<std::string> dirichlet = {"left", "right", "top"};
  for (const std::string solver : {"petsc-mumps", "petsc-iterative"}) {
    std::vector<testing::StokesErrors> e;
    for (int cells : {16, 32, 64}) {
      const Mesh mesh = testing::structured_rectangle(1.0, 1.0, cells, cells);
      const testing::StokesErrors direct = testing::stokes_mms::solve(mesh, dirichlet, "bottom");
      e.push_back(testing::stokes_mms::solve(mesh, dirichlet, "bottom", [&](PenalisedStokes& s) {
        s.set_linear_solver(solver, small(1e-12, 1000));
      }));
      EXPECT_NEAR(e.back().v_l2, direct.v_l2, 1e-6 * direct.v_l2) << solver << ", " << cells;
      EXPECT_NEAR(e.back().v_h1, direct.v_h1, 1e-6 * direct.v_h1) << solver << ", " << cells;
      EXPECT_NEAR(e.back().p_l2, direct.p_l2, 1e-6 * direct.p_l2) << solver << ", " << cells;
    }
    for (std::size_t k = 0; k + 1 < e.size(); ++k) {
      const double h = 1.0 / (16 << k);
      EXPECT_GE(testing::rate(e[k].v_l2, e[k + 1].v_l2, h, h / 2), 1.8) << solver;
      EXPECT_GE(testing::rate(e[k].v_h1, e[k + 1].v_h1, h, h / 2), 0.9) << solver;
      EXPECT_GE(testing::rate(e[k].p_l2, e[k + 1].p_l2, h, h / 2), 0.9) << solver;
    }
  }
}

// A stop asked of one rank is every rank's (common/interrupt.hpp agree_on_interrupts):
// on two ranks (ctest Mpi.PetscSolversOnTwoRanks) only the last rank is asked, and
// every rank's poll says so, with that rank's signal; once cleared, no poll does.
TEST(PetscSolver, AStopAskedOfOneRankIsEveryRanks) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const PetscSolver solver("petsc-mumps", small(1e-10, 10));  // PETSc started: the agreement too
  if (launched_rank() == launched_ranks() - 1) request_interrupt(SIGTERM);
  EXPECT_TRUE(interrupt_requested());
  EXPECT_EQ(interrupt_signal(), SIGTERM);
  clear_interrupt();
  EXPECT_FALSE(interrupt_requested());
}

// A non-finite entry in one rank's rows alone fails every rank (on_every_rank), before
// the collective factorisation or solve that the other ranks would otherwise wait in
// for ever: on two ranks (ctest Mpi.PetscSolversOnTwoRanks, whose time limit catches
// a hang) only the last rank's matrix, then its right-hand side, holds a NaN.
TEST(PetscSolver, ANonFiniteEntryOnOneRankFailsEveryRank) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  PetscSolver solver("petsc-mumps", small(1e-10, 10));
  const int n = 400;
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  solver.set_locality_order(order);
  const std::vector<char> here = solver.rows_here();  // empty: all (one rank)
  const auto held = [&here](int i) { return here.empty() || here[static_cast<std::size_t>(i)]; };
  std::vector<Eigen::Triplet<double>> entries;
  int last_held = -1;
  for (int i = 0; i < n; ++i) {
    if (!held(i)) continue;
    last_held = i;
    for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j) entries.emplace_back(i, j, i == j ? 2.0 : -1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  solver.analyze(A);
  solver.factorize(A);
  const bool last_rank = launched_rank() == launched_ranks() - 1;
  Eigen::SparseMatrix<double> broken = A;
  if (last_rank) broken.coeffRef(last_held, last_held) = std::nan("");
  EXPECT_THROW(solver.factorize(broken), SolverFailure);
  solver.factorize(A);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i)
    if (held(i)) b[i] = 1.0;
  EXPECT_NO_THROW(solver.solve(b));
  if (last_rank) b[last_held] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(solver.solve(b), SolverFailure);
}

// Debian's PETSc links SuperLU_DIST, whose initialiser, run when the plugin is loaded,
// tells the C allocator never to map a block of its own nor give memory back
// (M_MMAP_MAX = 0, M_TRIM_THRESHOLD = -1): the iterative set-up's freed blocks then stay
// resident, and a run's later passes peak higher. The loader sets them back
// (common/plugin_loader.cpp): a large block is mapped on its own and unmapped when freed.
TEST(PetscSolver, LoadingThePluginLeavesLargeBlocksGivenBackToTheSystem) {
  if (!have_petsc()) GTEST_SKIP() << "built without PETSc";
  const PetscSolver solver("petsc-iterative", small(1e-10, 100));
  constexpr std::size_t size = std::size_t{64} << 20;
  const std::size_t before = mallinfo2().hblkhd;
  auto* block = static_cast<volatile char*>(std::malloc(size));
  ASSERT_NE(block, nullptr);
  block[0] = 1;
  const std::size_t during = mallinfo2().hblkhd;
  std::free(const_cast<char*>(block));
  EXPECT_GE(during, before + size) << "a 64 MiB block was not mapped on its own, so it is never given back";
  EXPECT_LT(mallinfo2().hblkhd, during) << "the block was not unmapped when freed";
}

TEST(PetscSolver, WithoutThePluginItIsASolverFailureNamingThePackage) {
  if (have_petsc()) GTEST_SKIP() << "built with PETSc";
  try {
    PetscSolver solver("petsc-iterative", {});
    ADD_FAILURE() << "no plugin, yet a solver";
  } catch (const SolverFailure& e) {
    EXPECT_NE(std::string(e.what()).find("libpetsc-real-dev"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fsi::petsc_solver_test
