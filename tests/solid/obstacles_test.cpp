// [[obstacles]] with contact.gap = "normal" (SPEC §9): signed distances of polygons and
// half-planes against closed forms (polygons are not accepted in a case yet), and a beam resting on several obstacles at once.
#include <gtest/gtest.h>

#include <cmath>

#include "io/case.hpp"
#include "run/structure_setup.hpp"
#include "solid/relinearised_contact.hpp"
#include "solid/signed_distance.hpp"

namespace fsi {
namespace {

TEST(SignedDistance, PolygonInsideOutsideEdgeAndCorner) {
  // The unit square, clockwise: the orientation must not matter.
  const PolygonObstacle square({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
  const SignedDistance above = square.at(Point(0.5, 1.25));
  EXPECT_NEAR(above.d, 0.25, 1e-15);
  EXPECT_NEAR(above.n.y(), 1.0, 1e-15);
  const SignedDistance inside = square.at(Point(0.5, 0.9));
  EXPECT_NEAR(inside.d, -0.1, 1e-15);
  EXPECT_NEAR(inside.n.y(), 1.0, 1e-15);  // towards the nearest side, out of the square
  const SignedDistance corner = square.at(Point(1.3, 1.4));
  EXPECT_NEAR(corner.d, 0.5, 1e-15);
  EXPECT_NEAR(corner.n.x(), 0.6, 1e-15);
  EXPECT_NEAR(corner.n.y(), 0.8, 1e-15);
  const SignedDistance on = square.at(Point(1.0, 0.5));
  EXPECT_EQ(on.d, 0.0);
  EXPECT_NEAR(on.n.x(), 1.0, 1e-15);  // the edge's outward normal
  const HalfPlaneObstacle floor(Point(0, -1), Point(0, 2));
  EXPECT_NEAR(floor.at(Point(3, 0.5)).d, 1.5, 1e-15);
  EXPECT_NEAR(floor.at(Point(3, 0.5)).n.y(), 1.0, 1e-15);
}

// The §7.1 beam (clamped at x = 0) pressed by f = (0, −1e5) onto the obstacles of `toml`.
struct Rested {
  StructureSetup s;
  ContactSolution solution;
};

Rested rest_on(const std::string& obstacles, const std::string& solver = "active-set", const std::string& top = "") {
  const std::string text = top + R"(name = "obstacles"
[structure]
L = 0.06
H = 0.005
E = 3.0e5
nu = 0.3
f = [0.0, -1.0e5]
h = 0.001
[contact]
gap = "normal"
boundary = "all"
solver = ")" + solver + "\"\n" + obstacles;
  const Case c = load_case_text(text, "obstacles.toml");
  Rested r;
  r.s = make_structure(c, make_structure_mesh(c), nullptr);
  r.solution = r.s.gap->solve(*r.s.solver, r.s.b_applied);
  return r;
}

const std::string kTwoDisks = R"(
[[obstacles]]
shape = "disk"
x0 = 0.03
y0 = -0.0065
r = 0.005
[[obstacles]]
shape = "disk"
x0 = 0.055
y0 = -0.012
r = 0.005
)";

TEST(Obstacles, ABeamRestsOnTwoDisksAtOnce) {
  const Rested r = rest_on(kTwoDisks);
  const double diam = diameter(r.s.mesh());
  const auto per = r.s.gap->per_obstacle(*r.s.solver, r.solution);
  ASSERT_EQ(per.size(), 2u);
  for (const auto& o : per) {
    EXPECT_GT(o.active_nodes, 0);
    EXPECT_GT(o.force.y(), 0.0);  // the obstacles push up
  }
  EXPECT_GE(r.s.gap->min_gap(r.s.mesh(), r.solution.u), -1e-10 * diam);
  EXPECT_GE(r.solution.qp.alpha.minCoeff(), 0.0);
  EXPECT_LT(r.solution.qp.kkt.max(), 1e-12);
  const Rested ipopt = rest_on(kTwoDisks, "ipopt");
  const double scale = r.solution.u.cwiseAbs().maxCoeff();
  EXPECT_LT((r.solution.u - ipopt.solution.u).cwiseAbs().maxCoeff(), 1e-8 * scale);
}

// No obstacle at all (obstacles = []): no contact row, the beam hangs free.
TEST(Obstacles, AnEmptyListMeansNoContact) {
  const Rested r = rest_on("", "active-set", "obstacles = []\n");
  EXPECT_EQ(r.solution.qp.alpha.size(), 0);
  EXPECT_TRUE(std::isinf(r.s.gap->min_gap(r.s.mesh(), r.solution.u)));
}

// A flat floor's signed distance is linear: the first linearisation is exact, so the
// second QP only confirms it.
TEST(Obstacles, AHalfPlaneNeedsNoSecondLinearisation) {
  Rested r = rest_on(R"(
[[obstacles]]
shape = "half-plane"
point = [0.0, -0.003]
normal = [0.0, 1.0]
)");
  EXPECT_EQ(r.s.gap->linearisations(), 2);
  EXPECT_GE(r.s.gap->min_gap(r.s.mesh(), r.solution.u), -1e-10 * diameter(r.s.mesh()));
  EXPECT_GT(r.solution.qp.active_count(), 0);
}

}  // namespace
}  // namespace fsi
