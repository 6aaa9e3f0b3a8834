// improve_angles (mesh/angle_improvement.hpp): it never lowers the smallest angle nor
// turns a triangle over, keeps fixed vertices where they are and sliding ones on
// their segment, and does raise the angles of a poor mesh.
#include "mesh/angle_improvement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace fsi::angle_improvement_test {
namespace {

double min_angle(const std::vector<Point>& v, const std::vector<std::array<int, 3>>& t) {
  double q = INFINITY;
  for (const auto& tri : t)
    q = std::min(q, sine_squared_min_angle(v[tri[0]], v[tri[1]], v[tri[2]]));
  return std::asin(std::sqrt(std::max(q, 0.0))) * 180 / std::numbers::pi;
}

TEST(AngleImprovement, QualityIsTheSineOfTheSmallestAngle) {
  EXPECT_NEAR(sine_squared_min_angle({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}), 0.75,
              1e-15);                                                       // 60°
  EXPECT_NEAR(sine_squared_min_angle({0, 0}, {2, 0}, {0, 1}), 0.2, 1e-15);  // atan(1/2): sin² = 1/5
  EXPECT_EQ(sine_squared_min_angle({0, 0}, {0, 1}, {1, 0}), -1);            // clockwise
}

// The unit square as a 12 × 12 grid of right triangles, every inner vertex moved at
// random by up to 0.3 of the spacing (no triangle turns over: their heights are 0.71
// of it) — a poor mesh. The corners are fixed, the sides' vertices slide along them.
struct Poor {
  std::vector<Point> v;
  std::vector<std::array<int, 3>> t;
  std::vector<Freedom> freedom;
};

Poor poor_mesh() {
  const int n = 12;
  Poor p;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Point x(i / double(n), j / double(n));
      Freedom f{Freedom::free};
      const bool side_x = i == 0 || i == n, side_y = j == 0 || j == n;
      if (side_x && side_y)
        f = {Freedom::fixed};
      else if (side_x)
        f = {Freedom::line, Point(double(i) / n, 0), Point(double(i) / n, 1)};
      else if (side_y)
        f = {Freedom::line, Point(0, double(j) / n), Point(1, double(j) / n)};
      else {
        Point d(u(random), u(random));
        while (d.norm() > 1) d = Point(u(random), u(random));
        x += 0.3 / n * d;
      }
      p.v.push_back(x);
      p.freedom.push_back(f);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      p.t.push_back({a, a + 1, a + n + 2});
      p.t.push_back({a, a + n + 2, a + n + 1});
    }
  return p;
}

bool on_side(const Point& x) {
  return x.x() == 0 || x.x() == 1 || x.y() == 0 || x.y() == 1;
}

TEST(AngleImprovement, RaisesAPoorMeshsAnglesAndKeepsItValid) {
  Poor p = poor_mesh();
  const double before = min_angle(p.v, p.t);
  const std::vector<Point> start = p.v;
  const AngleReport r = improve_angles(p.v, p.t, p.freedom, {});
  const double after = min_angle(p.v, p.t);
  EXPECT_LT(before, 30);  // the grid's 45° triangles, some squeezed
  EXPECT_GT(after, before + 10);
  EXPECT_GT(r.moves, 50);
  for (const auto& tri : p.t)
    EXPECT_GT(sine_squared_min_angle(p.v[tri[0]], p.v[tri[1]], p.v[tri[2]]), 0);
  for (std::size_t i = 0; i < p.v.size(); ++i) {
    if (p.freedom[i].kind == Freedom::fixed) {
      EXPECT_EQ(p.v[i], start[i]) << i;  // corners
    }
    if (p.freedom[i].kind == Freedom::line) {  // slid along its side only
      EXPECT_TRUE(on_side(p.v[i])) << i;
      EXPECT_TRUE(p.v[i].x() == start[i].x() || p.v[i].y() == start[i].y()) << i;
    }
  }
  // Still a triangulation of the square: the areas add up to 1.
  double area = 0;
  for (const auto& tri : p.t) {
    const Point a = p.v[tri[1]] - p.v[tri[0]], b = p.v[tri[2]] - p.v[tri[0]];
    area += (a.x() * b.y() - a.y() * b.x()) / 2;
  }
  EXPECT_NEAR(area, 1, 1e-12);
}

TEST(AngleImprovement, NeverLowersTheSmallestAngleWhateverTheTarget) {
  for (double target : {10.0, 30.0, 50.0, 60.0}) {
    Poor p = poor_mesh();
    const double before = min_angle(p.v, p.t);
    improve_angles(p.v, p.t, p.freedom, {.target_deg = target, .rounds = 3});
    EXPECT_GE(min_angle(p.v, p.t), before) << target;
  }
}

}  // namespace
}  // namespace fsi::angle_improvement_test
