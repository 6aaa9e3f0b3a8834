// contact.gap = "normal" (SPEC §9): the signed distance to the disk, re-linearised
// about the current state, against the paper's eq. (15) on §7.1. Where the structure
// slides along the obstacle, eq. (15), linearised at the reference abscissa, misses
// ψ(X1 + u1) − ψ(X1) − ψ'(X1) u1 ≈ ψ''(X1) u1²/2 and penetrates by about u1²/(2r) at
// the top of the disk; "normal" holds the exact gap at every candidate vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "io/case.hpp"
#include "solid/contact_gap.hpp"
#include "run/structure_setup.hpp"
#include "solid/normal_contact.hpp"
#include "solid/relinearised_contact.hpp"

namespace fsi::normal_contact_test {
namespace {

const std::string kFig5 = std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.1-fig5-coarse.toml";

TEST(SignedDistance, DiskDistanceAndNormal) {
  const DiskObstacle disk(Point(1, 2), 0.5);
  const SignedDistance out = disk.at(Point(1, 3));
  EXPECT_DOUBLE_EQ(out.d, 0.5);
  EXPECT_DOUBLE_EQ(out.n.x(), 0.0);
  EXPECT_DOUBLE_EQ(out.n.y(), 1.0);
  const SignedDistance in = disk.at(Point(1.3, 2));
  EXPECT_NEAR(in.d, -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(in.n.x(), 1.0);
  const DiskObstacle other(Point(5, 2), 1.0);
  const NearestObstacle n = nearest({&disk, &other}, Point(4.5, 2));
  EXPECT_EQ(n.index, 1);
  EXPECT_NEAR(n.gap.d, -0.5, 1e-15);
}

struct Solved {
  StructureSetup s;
  ContactSolution solution;
  double min_gap = 0;
  int linearisations = 0;
};

Solved solve(const std::vector<std::string>& sets) {
  const Case c = load_case(kFig5, sets);
  Solved out;
  out.s = make_structure(c, make_structure_mesh(c), nullptr);
  ContactGap& gap = *out.s.gap;
  out.solution = gap.solve(*out.s.solver, out.s.b_applied);
  out.min_gap = gap.min_gap(out.s.mesh(), out.solution.u);
  out.linearisations = gap.linearisations();
  return out;
}

// The active vertex's horizontal displacement predicts the paper's penetration.
double predicted_penetration(const Solved& p, double r) {
  const auto active = active_vertices(*p.s.solver, p.solution);
  EXPECT_FALSE(active.empty());
  double worst = 0;  // u's first nv entries are u1
  for (int v : active) worst = std::max(worst, p.solution.u[v] * p.solution.u[v] / (2 * r));
  return worst;
}

TEST(NormalContact, HoldsTheExactGapWhereThePapersGapPenetrates) {
  for (const char* load : {"structure.f=[0,-1e4]", "structure.f=[0,-1e5]"}) {
    const Solved paper = solve({load});
    const Solved normal = solve({load, "contact.gap=normal"});
    const double diam = diameter(paper.s.mesh());
    // "normal": the exact gap at every candidate vertex, KKT to round-off.
    EXPECT_GE(normal.min_gap, -1e-10 * diam) << load;
    EXPECT_LT(normal.solution.qp.kkt.max(), 1e-12) << load;
    EXPECT_GT(normal.linearisations, 1) << load;
    EXPECT_LE(normal.linearisations, 20) << load;
    // "paper" penetrates by about u1²/(2r) at its active vertex (r = 5 mm here).
    const double predicted = predicted_penetration(paper, 0.005);
    EXPECT_LT(paper.min_gap, -1e-6) << load;
    EXPECT_GT(-paper.min_gap, 0.5 * predicted) << load;
    EXPECT_LT(-paper.min_gap, 2.0 * predicted) << load;
    // Close where the linearisation is good: max |u| within 1 %.
    const double a = paper.solution.u.cwiseAbs().maxCoeff(), b = normal.solution.u.cwiseAbs().maxCoeff();
    EXPECT_LT(std::abs(a - b), 0.01 * a) << load;
  }
}

TEST(NormalContact, IpoptAndTheActiveSetSolverAgree) {
  const Solved active = solve({"contact.gap=normal"});
  const Solved ipopt = solve({"contact.gap=normal", "contact.solver=ipopt"});
  const double scale = active.solution.u.cwiseAbs().maxCoeff();
  EXPECT_LT((active.solution.u - ipopt.solution.u).cwiseAbs().maxCoeff(), 1e-8 * scale);
  EXPECT_GE(ipopt.min_gap, -1e-10 * diameter(ipopt.s.mesh()));
}

// "all": every boundary vertex off Γ_D is a candidate; on §7.1 only Γ_C's touch, so
// the answer is that of "Gamma_C" (the same vertices carry the contact).
TEST(NormalContact, AllBoundaryCandidatesFindTheSameContact) {
  const Solved gc = solve({"contact.gap=normal"});
  const Solved all = solve({"contact.gap=normal", "contact.boundary=all"});
  EXPECT_GT(all.solution.qp.alpha.size(), gc.solution.qp.alpha.size());
  const double scale = gc.solution.u.cwiseAbs().maxCoeff();
  EXPECT_LT((gc.solution.u - all.solution.u).cwiseAbs().maxCoeff(), 1e-9 * scale);
}

}  // namespace
}  // namespace fsi::normal_contact_test
