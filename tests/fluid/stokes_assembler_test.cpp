// StokesAssembler::share_rows (issue 32: each MPI rank assembles its own rows): a
// share's K and rhs are the whole system's rows it holds, empty and zero elsewhere,
// after a full assembly and after an update where χ changed; two complementary shares
// add up to the whole system; a share visits only the triangles that touch its rows.
// K freed and rebuilt, and the element loads computed when needed, give the same numbers;
// the bubbles recovered by shares of the triangles add up to the whole ones.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/stokes_assembler.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::stokes_assembler_test {
namespace {

struct Channel {
  Channel() : mesh(testing::structured_rectangle(2.0, 1.0, 12, 6)) {
    for (const char* name : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(name));
    bc.g = [](const Point& x) { return Point(x.y() * (1 - x.y()), 0); };
    bc.tractions.push_back({mesh.label("right"), [](const Point&) { return Point(-0.5, 0.1); }});
  }
  StokesAssembler assembler() const {
    return StokesAssembler(mesh, 0.01, [](const Point& x) { return Point(x.y(), -9.81); }, bc);
  }
  // χ = 1 on the triangles whose first vertex lies left of x.
  Eigen::VectorXd chi(double x) const {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(mesh.num_triangles());
    for (int t = 0; t < mesh.num_triangles(); ++t) c[t] = mesh.vertices[mesh.triangles[t][0]].x() < x ? 1.0 : 0.0;
    return c;
  }
  Mesh mesh;
  FluidBoundaryConditions bc;
};

// K with only the rows r with here[r] kept.
Eigen::SparseMatrix<double> rows_of(const Eigen::SparseMatrix<double>& K, const std::vector<char>& here) {
  Eigen::SparseMatrix<double> out = K;
  out.prune([&here](Eigen::Index row, Eigen::Index, double) { return here[static_cast<std::size_t>(row)] != 0; });
  return out;
}

void expect_rows(const StokesAssembler& share, const StokesAssembler& whole, const std::vector<char>& here,
                 const char* when) {
  const Eigen::SparseMatrix<double> expected = rows_of(whole.matrix(), here);
  EXPECT_EQ(share.matrix().nonZeros(), expected.nonZeros()) << when;
  EXPECT_LE((share.matrix() - expected).norm(), 1e-12 * whole.matrix().norm()) << when;
  for (std::size_t r = 0; r < here.size(); ++r) {
    const double want = here[r] ? whole.rhs()[static_cast<Eigen::Index>(r)] : 0.0;
    ASSERT_NEAR(share.rhs()[static_cast<Eigen::Index>(r)], want, 1e-12 * whole.rhs().norm()) << when << ", row " << r;
  }
}

TEST(StokesAssembler, SomeRowsAreTheWholeMatrixsRowsAndTwoSharesAddUpToIt) {
  const Channel channel;
  StokesAssembler whole = channel.assembler();
  const int n = whole.unknowns();
  std::vector<char> first(static_cast<std::size_t>(n)), second(first.size());
  for (int r = 0; r < n; ++r) first[static_cast<std::size_t>(r)] = r % 3 != 1, second[static_cast<std::size_t>(r)] = r % 3 == 1;
  StokesAssembler a = channel.assembler(), b = channel.assembler();
  a.share_rows(first);
  b.share_rows(second);
  const double eps = 1e-4;
  for (const double x : {0.5, 0.7}) {  // a full assembly, then an update where χ changed
    whole.assemble(channel.chi(x), eps);
    a.assemble(channel.chi(x), eps);
    b.assemble(channel.chi(x), eps);
    const char* when = x == 0.5 ? "full assembly" : "update";
    expect_rows(a, whole, first, when);
    expect_rows(b, whole, second, when);
    EXPECT_LE((a.matrix() + b.matrix() - whole.matrix()).norm(), 1e-12 * whole.matrix().norm()) << when;
    EXPECT_LE((a.rhs() + b.rhs() - whole.rhs()).norm(), 1e-12 * whole.rhs().norm()) << when;
  }
}

TEST(StokesAssembler, AShareVisitsOnlyTheTrianglesTouchingItsRows) {
  const Channel channel;
  const Mesh& mesh = channel.mesh;
  StokesAssembler a = channel.assembler();
  EXPECT_EQ(a.triangles_here(), mesh.num_triangles());
  // The unknowns of the vertices left of x = 0.5 (each has its pressure's at least):
  // the triangles with such a vertex are visited, the others not.
  const auto left = [&mesh](int v) { return mesh.vertices[v].x() < 0.5; };
  std::vector<char> here(static_cast<std::size_t>(a.unknowns()), 0);
  int touching = 0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    touching += left(tri[0]) || left(tri[1]) || left(tri[2]);
    const std::array<int, 9> dof = a.element_dofs(t);
    for (std::size_t k = 0; k < 9; ++k)
      if (dof[k] >= 0 && left(tri[k % 3])) here[static_cast<std::size_t>(dof[k])] = 1;
  }
  a.share_rows(here);
  EXPECT_EQ(a.triangles_here(), touching);
  EXPECT_LT(touching, mesh.num_triangles());
  a.share_rows({});  // all the rows again
  EXPECT_EQ(a.triangles_here(), mesh.num_triangles());
}

TEST(StokesAssembler, AShareMustHaveOneFlagPerUnknown) {
  const Channel channel;
  StokesAssembler a = channel.assembler();
  EXPECT_THROW(a.share_rows(std::vector<char>(static_cast<std::size_t>(a.unknowns()) + 1, 1)), std::invalid_argument);
}

// K's entries are addressed by their 16-bit offset in their column: a column longer
// than 65 535 entries (a vertex shared by more than 21 844 triangles, all of its three
// unknowns free) is refused by name, never written past. A fan of 21 845 thin
// triangles around one vertex, tractions only, is the smallest such mesh.
TEST(StokesAssembler, AVertexInMoreTrianglesThanTheOffsetsAddressIsRefusedByName) {
  for (const int m : {21844, 21845}) {
    Mesh fan;
    fan.vertices.push_back(Point(0, 0));
    for (int i = 0; i < m; ++i) {
      const double a = 2 * M_PI * i / m;
      fan.vertices.push_back(Point(std::cos(a), std::sin(a)));
    }
    const int wall = fan.add_label("wall");
    for (int i = 0; i < m; ++i) {
      const int a = 1 + i, b = 1 + (i + 1) % m;
      fan.triangles.push_back({0, a, b});
      fan.boundary_edges.push_back({{a, b}, wall});
    }
    FluidBoundaryConditions bc;
    bc.tractions.push_back({wall, [](const Point&) { return Point(0, 0); }});
    StokesAssembler assembler(fan, 1.0, [](const Point&) { return Point(0, 0); }, bc);
    const Eigen::VectorXd chi = Eigen::VectorXd::Zero(m);
    if (m == 21844) {
      assembler.assemble_full(chi, 1.0);  // 65 535 entries in the centre's columns: the limit
      EXPECT_EQ(assembler.matrix().col(0).nonZeros(), 65535);
    } else {
      try {
        assembler.assemble_full(chi, 1.0);
        FAIL() << "a column of 65 538 entries was accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("21 844 triangles"), std::string::npos) << e.what();
      }
    }
  }
}

// K's entries that differ from their mirror image across the diagonal, compared bit
// for bit (not to a tolerance).
long asymmetric_entries(const Eigen::SparseMatrix<double>& K) {
  long count = 0;
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      if (it.value() != K.coeff(it.col(), it.row())) ++count;
  return count;
}

// A symmetric K is symmetric bit for bit, not to round-off (the condensed element's
// products are not): PETSc reads K's columns as its rows (petsc_solver.cpp), so K must
// be its own transpose exactly, after a full assembly, after updates where χ changed,
// and in both viscous forms. Its lower triangle, MUMPS's, is the element's own.
TEST(StokesAssembler, ASymmetricOperatorIsItsOwnTransposeBitForBit) {
  const Channel channel;
  for (const ViscousForm form : {ViscousForm::symmetric, ViscousForm::gradient}) {
    StokesAssembler a = channel.assembler();
    a.set_viscous_form(form);
    ASSERT_TRUE(a.symmetric());
    a.assemble(channel.chi(0.7), 1e-5);
    EXPECT_EQ(asymmetric_entries(a.matrix()), 0) << "full assembly";
    a.assemble(channel.chi(0.9), 1e-5);
    a.assemble(channel.chi(0.6), 1e-5);
    EXPECT_EQ(asymmetric_entries(a.matrix()), 0) << "after two updates";
    StokesAssembler fresh = channel.assembler();
    fresh.set_viscous_form(form);
    fresh.assemble(channel.chi(0.6), 1e-5);
    EXPECT_LE((a.matrix() - fresh.matrix()).norm(), 1e-12 * fresh.matrix().norm());
  }
}

// What a solver that frees K asks of the assembler (WholeSolve, petsc-iterative): the
// element loads computed when needed, the offsets and K freed, K built anew by the next
// assembly. The same numbers bit for bit as an assembler that keeps them all, in K,
// the right-hand side and the fields (the bubbles read the loads too).
TEST(StokesAssembler, FreedAndRebuiltItAssemblesTheSameBitForBit) {
  const Channel channel;
  StokesAssembler kept = channel.assembler(), lean = channel.assembler();
  lean.keep_element_loads(false);
  lean.assemble(channel.chi(0.7), 1e-5);
  lean.release_offsets();
  lean.release_matrix();
  EXPECT_EQ(lean.matrix().nonZeros(), 0);
  kept.assemble(channel.chi(0.7), 1e-5);
  kept.forget_assembly();  // a full assembly, as the freed one's next is
  kept.assemble(channel.chi(0.9), 1e-5);
  lean.assemble(channel.chi(0.9), 1e-5);
  ASSERT_EQ(lean.matrix().nonZeros(), kept.matrix().nonZeros());
  EXPECT_EQ((lean.matrix() - kept.matrix()).norm(), 0.0);
  EXPECT_EQ((lean.rhs() - kept.rhs()).norm(), 0.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(kept.unknowns(), -1.0, 2.0);
  FluidSolution a, b;
  kept.fields(x, channel.chi(0.9), 1e-5, a);
  lean.fields(x, channel.chi(0.9), 1e-5, b);
  EXPECT_EQ((a.bubble - b.bubble).norm(), 0.0);
  lean.keep_element_loads(true);  // kept again: the same loads
  lean.forget_assembly();
  lean.assemble(channel.chi(0.9), 1e-5);
  EXPECT_EQ((lean.rhs() - kept.rhs()).norm(), 0.0);
}

// The bubbles of a range of triangles (a rank's share, WholeSolve) are the whole
// solution's there and zero elsewhere, so that the shares summed are the whole, bit
// for bit; the vertex fields are the whole solution's everywhere.
TEST(StokesAssembler, TheBubblesOfTwoSharesAddUpToTheWholeOnesBitForBit) {
  const Channel channel;
  StokesAssembler assembler = channel.assembler();
  assembler.assemble(channel.chi(0.7), 1e-5);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(assembler.unknowns(), -1.0, 2.0);
  const int nt = channel.mesh.num_triangles(), half = nt / 2;
  FluidSolution whole, first, second;
  assembler.fields(x, channel.chi(0.7), 1e-5, whole);
  assembler.fields(x, channel.chi(0.7), 1e-5, first, 0, half);
  assembler.fields(x, channel.chi(0.7), 1e-5, second, half, nt);
  ASSERT_GT(whole.bubble.cwiseAbs().minCoeff(), 0.0) << "a zero bubble would not tell the shares apart";
  EXPECT_EQ(first.bubble.rightCols(nt - half).norm(), 0.0);
  EXPECT_EQ(second.bubble.leftCols(half).norm(), 0.0);
  EXPECT_EQ((first.bubble + second.bubble - whole.bubble).norm(), 0.0);
  EXPECT_EQ((first.v1 - whole.v1).norm() + (second.v2 - whole.v2).norm() + (first.p - whole.p).norm(), 0.0);
}

}  // namespace
}  // namespace fsi::stokes_assembler_test
