// What the fluid picture shows, checked by its pixels: a structure from a Gmsh .geo
// script (a flap with a rounded end) in a box with two holes (a disk and a square)
// through `fsicontact run`. Each hole is drawn filled in the obstacle grey with a dark
// outline, the fluid shaded around it, and the structure's outline in white where the
// script puts it. Figure::pixel gives where a world point lands (the layout depends on
// the box and the width only), so each check looks at a known place.
#include <gtest/gtest.h>

#include <cairo.h>

#include <array>
#include <cmath>
#include <numbers>

#include "io/case.hpp"
#include "io/figure.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "support/cli.hpp"

namespace fsi::figure_content_test {
namespace {

namespace fs = std::filesystem;

// Ω_S0: (0, 0.285) × (0, 0.03) closed by a half disk of radius 0.015 on the right.
const char* kFlapGeo = R"(L = 0.3;  H = 0.03;  r = H / 2;
Point(1) = {0, 0, 0, h};
Point(2) = {L - r, 0, 0, h};
Point(3) = {L - r, r, 0, h};
Point(4) = {L, r, 0, h};
Point(5) = {L - r, H, 0, h};
Point(6) = {0, H, 0, h};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Circle(3) = {4, 3, 5};
Line(4) = {5, 6};
Line(5) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1};
Physical Curve("Gamma_D") = {5};
Physical Curve("Gamma_N") = {1, 2, 3, 4};
)";

const char* kCase = R"(name = "geo-flap-two-holes"
[structure]
shape = "geo"
geo = "flap.geo"
h = 0.01
[fluid]
h = 0.015
[[obstacles]]
shape = "disk"
x0 = 0.2
y0 = -0.1
r = 0.05
[[obstacles]]
shape = "polygon"
points = [[0.1, 0.1], [0.2, 0.1], [0.2, 0.2], [0.1, 0.2]]
[contact]
gap = "normal"
boundary = "all"
[coupling]
max_iterations = 0
[output]
vtu = false
)";

class Picture {
 public:
  explicit Picture(const fs::path& png) : surface_(cairo_image_surface_create_from_png(png.c_str())) {}
  ~Picture() { cairo_surface_destroy(surface_); }
  Picture(const Picture&) = delete;
  Picture& operator=(const Picture&) = delete;
  bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  // The pixel's (r, g, b), 0–255; x, y rounded to the pixel containing them.
  std::array<int, 3> rgb(double x, double y) const {
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const int w = cairo_image_surface_get_width(surface_), h = cairo_image_surface_get_height(surface_);
    if (i < 0 || j < 0 || i >= w || j >= h) return {-1, -1, -1};
    const unsigned char* row = cairo_image_surface_get_data(surface_) + j * cairo_image_surface_get_stride(surface_);
    const std::uint32_t p = reinterpret_cast<const std::uint32_t*>(row)[i];
    return {static_cast<int>((p >> 16) & 255), static_cast<int>((p >> 8) & 255), static_cast<int>(p & 255)};
  }
  // Over the 3 × 3 pixels around (x, y): the largest of min(r, g, b) (whitest) and the
  // smallest of max(r, g, b) (darkest).
  int whitest(const Point& at) const { return extreme(at, true); }
  int darkest(const Point& at) const { return extreme(at, false); }

 private:
  int extreme(const Point& at, bool white) const {
    int best = white ? -1 : 256;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        const std::array<int, 3> c = rgb(at.x() + di, at.y() + dj);
        best = white ? std::max(best, std::min({c[0], c[1], c[2]})) : std::min(best, std::max({c[0], c[1], c[2]}));
      }
    return best;
  }
  cairo_surface_t* surface_;
};

bool obstacle_grey(const std::array<int, 3>& c) {  // {0.82, 0.82, 0.82}: 209
  return std::abs(c[0] - 209) <= 2 && std::abs(c[1] - 209) <= 2 && std::abs(c[2] - 209) <= 2;
}

TEST(FigureContent, AGeoStructureAndTwoHolesAreDrawnWhereTheyAre) {
  const fs::path dir = testing::scratch_dir("figure-content");
  testing::write_text(dir / "flap.geo", kFlapGeo);
  testing::write_text(dir / "case.toml", kCase);
  const testing::CliRun r = testing::run_cli("run case.toml --out res -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const Picture png(dir / "res/fluid.png");
  ASSERT_TRUE(png.ok());
  const Case c = load_case((dir / "case.toml").string(), {});
  const Figure layout(fluid_figure_box(*c.fluid), kFluidFigureWidth, "");
  auto at = [&](double x, double y) { return layout.pixel(Point(x, y)); };

  // The disk: grey inside, a dark outline on its circle, the fluid's colours outside.
  for (const double frac : {0.0, 0.5, 0.8}) {
    const Point p = at(0.2 + frac * 0.05 * std::cos(1.0), -0.1 + frac * 0.05 * std::sin(1.0));
    EXPECT_TRUE(obstacle_grey(png.rgb(p.x(), p.y()))) << "inside the disk at " << frac << " r";
  }
  for (int k = 0; k < 8; ++k) {
    const double t = k * std::numbers::pi / 4;
    EXPECT_LT(png.darkest(at(0.2 + 0.05 * std::cos(t), -0.1 + 0.05 * std::sin(t))), 90) << "the disk's outline, " << k;
    const Point out = at(0.2 + 0.08 * std::cos(t), -0.1 + 0.08 * std::sin(t));
    EXPECT_FALSE(obstacle_grey(png.rgb(out.x(), out.y()))) << "outside the disk, " << k;
  }
  // The square: grey inside, outlined along its sides.
  for (const Point& q : {Point(0.15, 0.15), Point(0.11, 0.19), Point(0.19, 0.11)}) {
    const Point p = at(q.x(), q.y());
    EXPECT_TRUE(obstacle_grey(png.rgb(p.x(), p.y()))) << "inside the square at " << q.transpose();
  }
  for (const Point& q : {Point(0.15, 0.1), Point(0.2, 0.15), Point(0.15, 0.2), Point(0.1, 0.15)})
    EXPECT_LT(png.darkest(at(q.x(), q.y())), 90) << "the square's outline at " << q.transpose();
  for (const Point& q : {Point(0.15, 0.23), Point(0.23, 0.15), Point(0.07, 0.15)}) {
    const Point p = at(q.x(), q.y());
    EXPECT_FALSE(obstacle_grey(png.rgb(p.x(), p.y()))) << "outside the square at " << q.transpose();
  }
  // The structure's outline, white: its straight sides and its rounded end, where the
  // script puts them (at rest: coupling.max_iterations = 0).
  for (double x = 0.03; x < 0.28; x += 0.05) {
    EXPECT_GE(png.whitest(at(x, 0.0)), 230) << "the flap's bottom at x = " << x;
    EXPECT_GE(png.whitest(at(x, 0.03)), 230) << "the flap's top at x = " << x;
  }
  for (int k = -2; k <= 2; ++k) {
    const double t = k * std::numbers::pi / 5;
    EXPECT_GE(png.whitest(at(0.285 + 0.015 * std::cos(t), 0.015 + 0.015 * std::sin(t))), 230) << "its end, " << k;
  }
  // The fluid is shaded, not white, away from the outline (inside the box, in D).
  for (const Point& q : {Point(0.35, -0.3), Point(0.05, 0.35), Point(0.3, 0.1)})
    EXPECT_LT(png.whitest(at(q.x(), q.y())), 230) << "the fluid at " << q.transpose();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::figure_content_test
