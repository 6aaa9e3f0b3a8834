// Polygon obstacles as holes of the generated fluid box (SPEC §9): D is the box minus
// the polygons (and disks) exactly, each hole's edges lie on its polygon's sides, its
// corners are mesh vertices, every side is cut into at least two edges (also a side
// shorter than fluid.h, and with the band refinement, whose size field ignores the
// corners' sizes), and the labels Sigma_5_i follow the holes' order; the same for the
// body-fitted mesh of D minus a structure (fluid.method = "body-fitted").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/polygon.hpp"

namespace fsi::polygon_hole_test {
namespace {

constexpr double kH = 0.02;

// A square turned by 30° (counter-clockwise), a thin triangle with a side of 0.6 h
// (clockwise), and a disk between them.
std::vector<FluidHole> holes() {
  std::vector<Point> square;
  for (int k = 0; k < 4; ++k) {
    const double t = M_PI / 6 + k * M_PI / 2;
    square.emplace_back(0.3 + 0.1 * std::cos(t), 0.1 * std::sin(t));
  }
  const std::vector<Point> sliver = {{1.0, 0.1}, {1.2, 0.1 + 0.6 * kH}, {1.2, 0.1}};
  return {{0, 0, 0, square}, {0.7, -0.2, 0.08}, {0, 0, 0, sliver}};
}

FluidGeometry box(double h_near = 0) {
  FluidGeometry g{1.5, 0.5, 0.5, 0, 0, 0, kH};
  g.holes = holes();
  if (h_near > 0) g.h_near = h_near, g.band = {0.1, -0.2, 0.5, 0.2};
  return g;
}

// Summed in long double: in double the round-off of ~10⁴ terms reached 1.5e-13 of the
// total (measured), what the checks below must resolve.
double mesh_area(const Mesh& m) {
  long double a = 0;
  for (int t = 0; t < m.num_triangles(); ++t) a += m.area(t);
  return static_cast<double>(a);
}

// The area inside the disk's meshed circle: the polygon of its Sigma_5 edges.
double inscribed_area(const Mesh& m, int label, const Point& centre) {
  long double a = 0;
  for (const BoundaryEdge& e : m.edges_on(label)) {
    const Point p = m.vertices[e.v[0]] - centre, q = m.vertices[e.v[1]] - centre;
    a += std::abs(p.x() * q.y() - p.y() * q.x()) / 2;
  }
  return static_cast<double>(a);
}

void expect_polygon_hole(const Mesh& m, const std::vector<Point>& corners, int label) {
  const std::vector<BoundaryEdge> edges = m.edges_on(label);
  ASSERT_FALSE(edges.empty());
  // Round-off of the meshing in units of a power of two: coordinates are exact to a few ulps.
  const double tol = 1e-14;
  std::vector<int> per_side(corners.size(), 0);
  for (const BoundaryEdge& e : edges) {
    const Point a = m.vertices[e.v[0]], b = m.vertices[e.v[1]], mid = (a + b) / 2;
    EXPECT_LT(distance_to_boundary(corners, a), tol);
    EXPECT_LT(distance_to_boundary(corners, b), tol);
    EXPECT_LT(distance_to_boundary(corners, mid), tol) << "an edge cuts a corner";
    for (std::size_t k = 0; k < corners.size(); ++k)
      if (distance_to_segment(mid, corners[k], corners[(k + 1) % corners.size()]) < tol) ++per_side[k];
  }
  for (std::size_t k = 0; k < corners.size(); ++k) EXPECT_GE(per_side[k], 2) << "side " << k << " of the polygon";
  for (const Point& c : corners) {
    const std::vector<int> on = m.vertices_on(label);
    const bool found = std::any_of(on.begin(), on.end(), [&](int v) { return (m.vertices[v] - c).norm() < tol; });
    EXPECT_TRUE(found) << "corner (" << c.x() << ", " << c.y() << ") is not a vertex of the hole";
  }
}

// `structure_area`: what else D lacks (the body-fitted mesh's structure).
void expect_the_holes(const Mesh& m, double structure_area = 0) {
  const std::vector<FluidHole> h = holes();
  ASSERT_EQ(hole_labels(m).size(), 3u);
  expect_polygon_hole(m, h[0].corners, m.label("Sigma_5_1"));
  expect_polygon_hole(m, h[2].corners, m.label("Sigma_5_3"));
  const Point centre(h[1].x0, h[1].y0);
  for (int v : m.vertices_on(m.label("Sigma_5_2"))) EXPECT_NEAR((m.vertices[v] - centre).norm(), h[1].r, 1e-14);
  // |D| = box − the polygons − the disk's inscribed polygon: the triangles fill exactly that.
  const double expected = 1.5 * 1.0 - structure_area - std::abs(signed_area(h[0].corners)) - std::abs(signed_area(h[2].corners)) -
                          inscribed_area(m, m.label("Sigma_5_2"), centre);
  EXPECT_NEAR(mesh_area(m), expected, 1e-13 * expected);
  for (int t = 0; t < m.num_triangles(); ++t) ASSERT_GT(m.area(t), 0);
}

TEST(PolygonHoles, TheBoxMinusThePolygonsExactly) {
  const Mesh m = generate_fluid_mesh(box());
  expect_the_holes(m);
  // Sizes at most h, finer near the short side (its corners' sizes are half of it).
  EXPECT_LE(statistics(m).h_max, 1.5 * kH) << "Gmsh's edges reach about 1.4 h";
  EXPECT_GT(statistics(m).min_angle_deg, 15);
}

TEST(PolygonHoles, TheBandRefinementKeepsEverySideCut) {
  expect_the_holes(generate_fluid_mesh(box(0.005)));
}

TEST(PolygonHoles, TheBodyFittedMeshHasTheSameHoles) {
  // A 0.5 x 0.05 beam on the left wall above the holes, its outline in pieces of h.
  const std::vector<Point> corners = {{0, 0.3}, {0.5, 0.3}, {0.5, 0.35}, {0, 0.35}};
  std::vector<Point> outline = {corners[0]};
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const int n = static_cast<int>(std::ceil((corners[k + 1] - corners[k]).norm() / kH));
    for (int i = 1; i <= n; ++i) outline.push_back(corners[k] + (corners[k + 1] - corners[k]) * (double(i) / n));
  }
  const Mesh m = generate_fluid_mesh_around({box(), outline});
  expect_the_holes(m, 0.5 * 0.05);
  EXPECT_EQ(m.vertices_on(m.label("Gamma_u")).size(), outline.size());
}

}  // namespace
}  // namespace fsi::polygon_hole_test
