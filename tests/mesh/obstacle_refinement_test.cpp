// The refinement at the obstacles of fluid.h_obstacles (FluidGeometry::h_holes, a Gmsh
// size field): triangles of size h_holes at the holes' boundaries, growing by
// kBandGrowth per unit of distance from them, hF beyond; with a band, the smaller of
// the two sizes. The DFG channel with its cylinder (cases/dfg-2d2.toml), where the
// forces on the cylinder need the mesh there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "support/triangle_measures.hpp"

namespace fsi::obstacle_refinement_test {
namespace {

using testing::longest_edge;

FluidGeometry channel(double h_holes, double h_near = 0) {
  FluidGeometry g{2.2, 0.41, 0.0, 0.2, 0.2, 0.05, 0.04};
  g.h_holes = h_holes;
  g.h_near = h_near;
  g.band = {0.12, 0.1, 0.6, 0.3};
  return g;
}

// The largest ratio of a triangle's longest edge to the size the field asks for at
// its centroid, over the triangles within `reach` of the cylinder, and the far
// triangles' mean edge.
struct Sizes {
  double near_ratio_max = 0, far_mean = 0;
  int triangles = 0;
};

Sizes sizes(const FluidGeometry& g) {
  const Mesh m = generate_fluid_mesh(g, MeshGenerator::gmsh);
  Sizes s;
  s.triangles = m.num_triangles();
  const double reach = (g.h - g.h_holes) / kBandGrowth;
  int far = 0;
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& T = m.triangles[t];
    const Point c = (m.vertices[T[0]] + m.vertices[T[1]] + m.vertices[T[2]]) / 3;
    const double d = std::max((c - Point(g.x0, g.y0)).norm() - g.r, 0.0), e = longest_edge(m, t);
    const bool in_band = c.x() > g.band[0] && c.x() < g.band[2] && c.y() > g.band[1] && c.y() < g.band[3];
    double target = g.h_holes + kBandGrowth * d;
    if (g.h_near > 0 && in_band) target = std::min(target, g.h_near);
    if (d < reach) s.near_ratio_max = std::max(s.near_ratio_max, e / target);
    else if (!(g.h_near > 0 && in_band) && d > 2 * reach) s.far_mean += e, ++far;
  }
  s.far_mean /= far;
  return s;
}

TEST(ObstacleRefinement, SizesGrowFromTheObstacleAtTheBandsRate) {
  for (double h_holes : {0.004, 0.001}) {
    const Sizes s = sizes(channel(h_holes));
    // An edge of a Delaunay triangle of target size h reaches about 1.4 h.
    EXPECT_LT(s.near_ratio_max, 1.6) << h_holes;
    EXPECT_GT(s.far_mean, 0.7 * 0.04) << h_holes;
    EXPECT_LT(s.far_mean, 1.4 * 0.04) << h_holes;
  }
}

// With a band too, each triangle takes the smaller of the two sizes; and refining at
// the cylinder costs triangles in a ring, about 2.4 P / g (1/h_holes − 1/h_near) more
// (the estimate case checks add), a third of them under that estimate at most.
TEST(ObstacleRefinement, WithTheBandTheSmallerSizeWinsAndTheRingCostsItsEstimate) {
  const Sizes banded = sizes(channel(0, 0.005)), both = sizes(channel(0.001, 0.005));
  EXPECT_LT(both.near_ratio_max, 1.6);
  const double ring = 2.4 * 2 * M_PI * 0.05 / kBandGrowth * (1 / 0.001 - 1 / 0.005);
  const double added = both.triangles - banded.triangles;
  EXPECT_GT(added, 0.7 * ring);
  EXPECT_LT(added, 1.5 * ring);
}

// The lattice generator has no such field: it refuses rather than ignore it (the case
// reader refuses fluid.h_obstacles with fluid.mesher = "lattice" before).
TEST(ObstacleRefinement, TheLatticeGeneratorRefusesIt) {
  EXPECT_THROW(generate_fluid_mesh(channel(0.002), MeshGenerator::lattice), MeshError);
}

}  // namespace
}  // namespace fsi::obstacle_refinement_test
