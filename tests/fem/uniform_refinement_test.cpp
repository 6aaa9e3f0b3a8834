// The uniform refinement behind coupling.force_sampling: m² similar triangles per
// triangle, counter-clockwise, edge points shared, and P the exact P1 interpolation.
#include "fem/uniform_refinement.hpp"

#include <gtest/gtest.h>

namespace fsi::uniform_refinement_test {
namespace {

Mesh two_triangles() {
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1.5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

double signed_area(const Mesh& m, int t) {
  const auto& v = m.triangles[t];
  const Point a = m.vertices[v[1]] - m.vertices[v[0]], b = m.vertices[v[2]] - m.vertices[v[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

TEST(UniformRefinement, CutsEachTriangleIntoMSquaredSharingEdgePoints) {
  const Mesh coarse = two_triangles();
  for (int m : {1, 2, 3, 5}) {
    const UniformRefinement r = refine_uniformly(coarse, m);
    ASSERT_EQ(r.fine.num_triangles(), 2 * m * m);
    EXPECT_EQ(r.fine.num_vertices(), 2 * (m + 1) * (m + 2) / 2 - (m + 1));  // the shared edge once
    for (int t = 0; t < r.fine.num_triangles(); ++t) {
      const int parent = t < m * m ? 0 : 1;
      EXPECT_NEAR(signed_area(r.fine, t), signed_area(coarse, parent) / (m * m), 1e-14) << "m " << m << " t " << t;
    }
    // P interpolates the coordinates (linear) exactly; its rows sum to 1.
    Eigen::VectorXd x(4), y(4);
    for (int v = 0; v < 4; ++v) x[v] = coarse.vertices[v].x(), y[v] = coarse.vertices[v].y();
    const Eigen::VectorXd fx = r.P * x, fy = r.P * y;
    for (int v = 0; v < r.fine.num_vertices(); ++v) {
      EXPECT_NEAR(fx[v], r.fine.vertices[v].x(), 1e-14);
      EXPECT_NEAR(fy[v], r.fine.vertices[v].y(), 1e-14);
      EXPECT_NEAR(r.P.row(v).sum(), 1.0, 1e-14);
    }
  }
  EXPECT_THROW(refine_uniformly(coarse, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::uniform_refinement_test
