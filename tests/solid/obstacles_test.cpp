// [[obstacles]] with contact.gap = "normal" (SPEC §9): signed distances of polygons and
// half-planes against closed forms, a beam resting on several obstacles at once, on a
// block's corner and on a wedge's tip.
#include <gtest/gtest.h>

#include <cmath>

#include "io/case.hpp"
#include "solid/contact_gap.hpp"
#include "run/structure_setup.hpp"
#include "solid/relinearised_contact.hpp"
#include "solid/signed_distance.hpp"

namespace fsi::obstacles_test {
namespace {

TEST(SignedDistance, PolygonInsideOutsideEdgeAndCorner) {
  // The unit square, clockwise: the orientation must not matter.
  const PolygonObstacle square({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0.0);
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

// A polygon's distance less its margin: its corners become arcs of that radius.
TEST(SignedDistance, APolygonsMarginRoundsItsCorners) {
  const PolygonObstacle square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.01);
  EXPECT_NEAR(square.at(Point(0.5, 1.25)).d, 0.24, 1e-15);
  const Point beyond(1 + 0.01 / std::sqrt(2.0), 1 + 0.01 / std::sqrt(2.0));  // on the corner's arc
  EXPECT_NEAR(square.at(beyond).d, 0.0, 1e-15);
  EXPECT_NEAR(square.at(beyond).n.x(), 1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(square.at(Point(1.0, 0.5)).d, -0.01, 1e-15);  // on the edge: inside the margin
}

// The beam rests on every obstacle of `obstacles` (each pushes up), within `max_passes`
// linearisations, with the exact gap, the KKT conditions, and both QP solvers agreeing.
void expect_settled_contact(const std::string& obstacles, std::size_t count, int max_passes) {
  const Rested r = rest_on(obstacles);
  const double diam = diameter(r.s.mesh());
  EXPECT_LE(r.s.gap->linearisations(), max_passes);
  const auto per = r.s.gap->per_obstacle(*r.s.solver, r.solution);
  ASSERT_EQ(per.size(), count);
  for (const auto& o : per) {
    EXPECT_GT(o.active_nodes, 0);
    EXPECT_GT(o.force.y(), 0.0);  // the obstacles push up
  }
  EXPECT_GE(r.s.gap->min_gap(r.s.mesh(), r.solution.u), -1e-10 * diam);
  EXPECT_GE(r.solution.qp.alpha.minCoeff(), 0.0);
  EXPECT_LT(r.solution.qp.kkt.max(), 1e-12);
  const Rested ipopt = rest_on(obstacles, "ipopt");
  const double scale = r.solution.u.cwiseAbs().maxCoeff();
  EXPECT_LT((r.solution.u - ipopt.solution.u).cwiseAbs().maxCoeff(), 1e-8 * scale);
}

TEST(Obstacles, ABeamRestsOnTwoDisksAtOnce) { expect_settled_contact(kTwoDisks, 2, 10); }  // measured 8

// The beam onto a block's corner (it bends over it) and onto a wedge's tip: the
// passes used to cycle at the corner (solid/signed_distance.hpp); with the margin they
// settle in a few.
std::string polygon(const std::string& points) {
  return "[[obstacles]]\nshape = \"polygon\"\npoints = " + points + "\n";
}

TEST(Obstacles, ABeamBendsOverABlocksCorner) {
  expect_settled_contact(polygon("[[0.02, -0.02], [0.04, -0.02], [0.04, -0.004], [0.02, -0.004]]"), 1, 4);  // measured 3
}

TEST(Obstacles, ABeamRestsOnAWedgesTip) {
  expect_settled_contact(polygon("[[0.035, -0.03], [0.055, -0.03], [0.045, -0.005]]"), 1, 4);  // measured 3
}

// A polygon flat side and a half-plane along it hold the beam alike: the margin, 1e-7
// diam, is all that differs.
TEST(Obstacles, APolygonsFlatSideActsAsAHalfPlane) {
  const Rested poly = rest_on("[[obstacles]]\nshape = \"polygon\"\npoints = [[-1, -0.003], [1, -0.003], [1, -1], [-1, -1]]\n");
  const Rested plane = rest_on("[[obstacles]]\nshape = \"half-plane\"\npoint = [0.0, -0.003]\nnormal = [0.0, 1.0]\n");
  const double diam = diameter(plane.s.mesh());
  EXPECT_LT((poly.solution.u - plane.solution.u).cwiseAbs().maxCoeff(), 2 * kPolygonMargin * diam);
  EXPECT_GT((poly.solution.u - plane.solution.u).cwiseAbs().maxCoeff(), 0.1 * kPolygonMargin * diam);
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
}  // namespace fsi::obstacles_test
