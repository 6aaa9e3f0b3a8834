// On one rank PETSc uses a symmetric K's arrays in place, without a copy
// (PetscSolver::factorize_values, the plugin's borrowed operator): the solution
// follows K's values when they change in the same arrays (the preconditioner or the
// factorisation is redone), when another matrix of the same pattern comes, and a K
// that is not its own transpose bit for bit is copied, never read as its transpose
// (petsc-iterative: a Krylov method reads all of it).
// Each answer against sequential MUMPS on the same matrix; a released set-up (before
// the next pass's matrices are built) cannot solve until the next factorisation. On two ranks (ctest
// Mpi.PetscSolversOnTwoRanks) the same answers come through the copying path.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/sparse_solver.hpp"
#include "fluid/stokes_assembler.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::petsc_in_place_test {
namespace {

// A channel with a penalised block, Poiseuille inflow, traction-free outflow.
struct Channel {
  Channel() : mesh(testing::structured_rectangle(2.0, 1.0, 24, 12)) {
    for (const char* name : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(name));
    bc.g = [](const Point& x) { return Point(x.y() * (1 - x.y()), 0); };
  }
  Eigen::VectorXd chi(double right) const {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(mesh.num_triangles());
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      const Point& v = mesh.vertices[mesh.triangles[t][0]];
      c[t] = v.x() > 0.8 && v.x() < right && v.y() > 0.3 && v.y() < 0.6 ? 1.0 : 0.0;
    }
    return c;
  }
  Mesh mesh;
  FluidBoundaryConditions bc;
};

LinearSolverOptions options() {
  LinearSolverOptions o(1e-12, 500);
  o.min_unknowns_per_rank = 1;  // these few unknowns on two ranks
  o.schur_mass = false;         // no pressure mass matrix to give: PETSc's selfp
  return o;
}

// MUMPS's LU of A: the reference, whatever A's symmetry.
Eigen::VectorXd reference(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b) {
  auto lu = make_sparse_solver("mumps-lu");
  lu->analyze(A);
  lu->factorize(A);
  return lu->solve(b);
}

void expect_solves(SparseDirectSolver& solver, const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                   const std::string& what) {
  solver.factorize(A);
  const Eigen::VectorXd expected = reference(A, b), x = solver.solve(b);
  EXPECT_LE((x - expected).norm(), 1e-8 * expected.norm()) << solver.name() << ", " << what;
  // The residual a solver that frees A computes with its own blocks is A's.
  const double residual = (b - A * x).norm() / b.norm();
  if (solver.detaches_from_operator()) {
    EXPECT_NEAR(solver.last_residual(), residual, 0.5 * residual + 1e-13) << solver.name() << ", " << what;
  }
}

TEST(PetscInPlace, TheSolutionFollowsTheOperatorsValuesAndArrays) {
#ifndef FSICONTACT_HAVE_PETSC
  GTEST_SKIP() << "built without PETSc";
#endif
  const Channel channel;
  for (const char* name : {"petsc-mumps", "petsc-iterative"}) {
    StokesAssembler assembler(channel.mesh, 0.01, [](const Point&) { return Point(0, -1); }, channel.bc);
    assembler.assemble(channel.chi(1.2), 1e-4);
    const Eigen::SparseMatrix<double>& K = assembler.matrix();
    ASSERT_TRUE(assembler.symmetric());
    auto solver = make_sparse_solver(name, options());
    solver->describe_system(assembler.pressure_unknowns(), true);
    solver->analyze(K);
    expect_solves(*solver, K, assembler.rhs(), "first");
    solver->release();  // the set-up freed: no solve until the next factorisation
    EXPECT_THROW(solver->solve(assembler.rhs()), std::logic_error) << name;
    const double* values = K.valuePtr();
    assembler.assemble(channel.chi(1.5), 1e-4);  // new values in the same arrays
    ASSERT_EQ(K.valuePtr(), values);
    expect_solves(*solver, K, assembler.rhs(), "new values in place");
    const Eigen::SparseMatrix<double> doubled = 2.0 * K;  // other arrays, the same pattern
    expect_solves(*solver, doubled, assembler.rhs(), "another matrix");
    // One pair of entries off the diagonal no longer mirror each other: K must be
    // copied, for read as rows its columns would be Kᵀ. (Not for petsc-mumps, told the
    // values are symmetric: its LDLᵀ reads one triangle, as sequential MUMPS's does.)
    if (std::string(name) == "petsc-mumps") continue;
    // The entry is B's (a pressure row, a velocity column): the iterative solver's
    // operator by blocks must then hold B of its own, not Bᵀ's transpose.
    Eigen::SparseMatrix<double> skewed = K;
    const std::vector<char> pressure = assembler.pressure_unknowns();
    for (int j = 0, done = 0; j < skewed.outerSize() && !done; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(skewed, j); it; ++it)
        if (pressure[static_cast<std::size_t>(it.row())] && !pressure[static_cast<std::size_t>(j)]) {
          it.valueRef() += 0.5 * std::abs(it.value()) + 1.0;
          done = 1;
          break;
        }
    expect_solves(*solver, skewed, assembler.rhs(), "not its own transpose");
  }
}

// The iterative solver sees each rank's velocity and pressure rows as views of the
// whole vector where they come in that order (the assembler's, on one rank), as
// copies otherwise (petsc_field_vectors.hpp): the unknowns numbered backwards, the
// pressure's first, give the same solution through the copies.
TEST(PetscInPlace, FieldsOutOfOrderSolveThroughCopies) {
#ifndef FSICONTACT_HAVE_PETSC
  GTEST_SKIP() << "built without PETSc";
#endif
  const Channel channel;
  StokesAssembler assembler(channel.mesh, 0.01, [](const Point&) { return Point(0, -1); }, channel.bc);
  assembler.assemble(channel.chi(1.2), 1e-4);
  const Eigen::Index n = assembler.matrix().rows();
  Eigen::PermutationMatrix<Eigen::Dynamic> backwards(n);
  for (Eigen::Index i = 0; i < n; ++i) backwards.indices()[i] = static_cast<int>(n - 1 - i);
  const Eigen::SparseMatrix<double> K = backwards * assembler.matrix() * backwards.transpose();
  const Eigen::VectorXd b = backwards * assembler.rhs();
  std::vector<char> pressure = assembler.pressure_unknowns();
  std::reverse(pressure.begin(), pressure.end());
  ASSERT_TRUE(pressure.front() && !pressure.back());
  auto solver = make_sparse_solver("petsc-iterative", options());
  solver->describe_system(pressure, true);
  solver->analyze(K);
  expect_solves(*solver, K, b, "the pressure's unknowns first");
}

}  // namespace
}  // namespace fsi::petsc_in_place_test
