// The band refinement of fluid.h_near (FluidGeometry::h_near): triangles of size
// h_near inside the band, growing by kBandGrowth per unit length away from it, hF
// beyond; the count follows the band's area over h_near².
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "support/triangle_measures.hpp"
#include "mesh/gmsh_io.hpp"

namespace fsi::band_refinement_test {
namespace {

using testing::longest_edge;

// Distance from x to the box [x0, y0, x1, y1] (0 inside).
double distance_to(const std::array<double, 4>& b, const Point& x) {
  const double dx = std::max({b[0] - x.x(), 0.0, x.x() - b[2]}), dy = std::max({b[1] - x.y(), 0.0, x.y() - b[3]});
  return std::hypot(dx, dy);
}

struct Sizes {
  double inside_max = 0;                   // longest edge of a triangle inside the band
  double transition_ratio_max = 0;         // longest edge / (h_near + growth · distance) in the transition
  double far_mean = 0;                     // mean longest edge beyond the transition
  int triangles = 0;
};

Sizes sizes(const FluidGeometry& g) {
  const Mesh m = generate_fluid_mesh(g);
  Sizes s;
  s.triangles = m.num_triangles();
  const double transition = (g.h - g.h_near) / kBandGrowth;
  int far = 0;
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& T = m.triangles[t];
    const Point c = (m.vertices[T[0]] + m.vertices[T[1]] + m.vertices[T[2]]) / 3;
    const double d = distance_to(g.band, c), e = longest_edge(m, t);
    if (d == 0) s.inside_max = std::max(s.inside_max, e);
    else if (d < transition) s.transition_ratio_max = std::max(s.transition_ratio_max, e / (g.h_near + kBandGrowth * d));
    else s.far_mean += e, ++far;
  }
  s.far_mean /= far;
  return s;
}

// §7.2's box, the band of docs/validation.md (every position of the beam).
FluidGeometry box(double h, double h_near) {
  FluidGeometry g{0.41, 0.5, 0.5, 0.2, -0.07, 0.05, h};
  g.h_near = h_near;
  g.band = {0, -0.06, 0.33, 0.05};
  return g;
}

TEST(BandRefinement, SizesFollowTheBandAndTheGrowth) {
  for (double h_near : {0.004, 0.002}) {
    const Sizes s = sizes(box(0.02, h_near));
    // An edge of a Delaunay triangle of target size h reaches about 1.4 h.
    EXPECT_LT(s.inside_max, 1.5 * h_near) << h_near;
    EXPECT_LT(s.transition_ratio_max, 1.6) << h_near;
    EXPECT_GT(s.far_mean, 0.7 * 0.02) << h_near;
    EXPECT_LT(s.far_mean, 1.4 * 0.02) << h_near;
  }
}

// Halving h_near multiplies the band's triangles by about 4, and the count stays
// near 2.4 · area / h² summed over band and far field (the estimate case checks use).
TEST(BandRefinement, TrianglesScaleWithTheBandsArea) {
  const int coarse = sizes(box(0.02, 0.002)).triangles, fine = sizes(box(0.02, 0.001)).triangles;
  const double band_area = 0.33 * 0.11;
  const double estimate = 2.4 * band_area / (0.001 * 0.001);
  EXPECT_GT(fine, 0.7 * estimate);
  EXPECT_LT(fine, 1.5 * estimate);
  EXPECT_GT(static_cast<double>(fine) / coarse, 3.0);
  EXPECT_LT(static_cast<double>(fine) / coarse, 4.5);
}

// Without h_near, the same call gives the uniform mesh (the band is ignored).
TEST(BandRefinement, NoBandWithoutHNear) {
  FluidGeometry g = box(0.01, 0);
  const Mesh banded = generate_fluid_mesh(g);
  g.band = {};
  const Mesh uniform = generate_fluid_mesh(g);
  EXPECT_EQ(banded.vertices, uniform.vertices);
  EXPECT_EQ(banded.triangles, uniform.triangles);
}

}  // namespace
}  // namespace fsi::band_refinement_test
