// The figures' pixels: paint_field (io/raster.hpp) colours each pixel by the P1 field
// at its centre, covering the mesh without gaps; write_png_atomically (io/png.hpp)
// is lossless (Cairo's own reader gives the same pixels back).
#include "io/raster.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "io/figure.hpp"
#include "io/png.hpp"

namespace fsi::raster_test {
namespace {

namespace fs = std::filesystem;

std::uint32_t packed(const Rgb& c) {
  const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(255 * v)); };
  return byte(c[0]) << 16 | byte(c[1]) << 8 | byte(c[2]);
}

// Channels of two packed colours differ by at most `tolerance` (the field is read off a
// table of 1024 colours).
bool close(std::uint32_t a, std::uint32_t b, int tolerance) {
  for (int shift : {0, 8, 16})
    if (std::abs(static_cast<int>((a >> shift) & 255) - static_cast<int>((b >> shift) & 255)) >
        tolerance)
      return false;
  return true;
}

TEST(Raster, PaintsEveryPixelOfTheMeshWithTheFieldAtItsCentre) {
  const int w = 64, h = 48;
  std::vector<std::uint32_t> pixels(w * h, 0xFFFFFFFF);
  // A square of 40 × 40 pixels at (10, 4), cut into four triangles through its centre;
  // the field f = x / 40 (linear: its P1 interpolant is exact).
  const std::vector<Point> at = {{10, 4}, {50, 4}, {50, 44}, {10, 44}, {30, 24}};
  const std::vector<std::array<int, 3>> tri = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  std::vector<double> t01;
  for (const Point& p : at) t01.push_back((p.x() - 10) / 40);
  paint_field({pixels.data(), 4 * w, {0, 0, w, h}}, at, tri, t01);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool inside = x >= 10 && x < 50 && y >= 4 && y < 44;
      const std::uint32_t p = pixels[y * w + x];
      if (!inside) {
        EXPECT_EQ(p, 0xFFFFFFFFu) << x << "," << y;
        continue;
      }
      EXPECT_TRUE(close(p, packed(viridis((x + 0.5 - 10) / 40)), 1))
          << x << "," << y << ": " << std::hex << p;
    }
}

TEST(Raster, KeepsToTheClip) {
  const int w = 20, h = 20;
  std::vector<std::uint32_t> pixels(w * h, 0);
  paint_field({pixels.data(), 4 * w, {5, 5, 15, 15}}, {{-10, -10}, {40, -10}, {-10, 40}},
              {{0, 1, 2}}, {0.5, 0.5, 0.5});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      EXPECT_EQ(pixels[y * w + x] != 0, x >= 5 && x < 15 && y >= 5 && y < 15) << x << "," << y;
}

// A triangle of no area (a structure folded flat, three vertices on a pixel row) covers
// no pixel centre and is skipped, not divided by its zero area; one with a NaN vertex too.
TEST(Raster, SkipsDegenerateTriangles) {
  const int w = 20, h = 20;
  std::vector<std::uint32_t> pixels(w * h, 0);
  paint_field({pixels.data(), 4 * w, {0, 0, w, h}}, {{2, 5.5}, {10, 5.5}, {18, 5.5}, {NAN, 3}},
              {{0, 1, 2}, {0, 1, 3}}, {0.5, 0.5, 0.5, 0.5});
  for (std::uint32_t p : pixels) EXPECT_EQ(p, 0u);
}

TEST(Png, IsLossless) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 37, 23);
  cairo_surface_flush(s);
  auto* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x)
      reinterpret_cast<std::uint32_t*>(data + y * stride)[x] =
          packed(viridis((x * 7 + y * 13) % 101 / 100.0));
  cairo_surface_mark_dirty(s);
  const fs::path path = fs::temp_directory_path() / "fsicontact-png-test.png";
  write_png_atomically(path, s);
  cairo_surface_t* back = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(back), CAIRO_STATUS_SUCCESS);
  ASSERT_EQ(cairo_image_surface_get_width(back), 37);
  ASSERT_EQ(cairo_image_surface_get_height(back), 23);
  const auto* read = cairo_image_surface_get_data(back);
  const int read_stride = cairo_image_surface_get_stride(back);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x)
      EXPECT_EQ(reinterpret_cast<const std::uint32_t*>(read + y * read_stride)[x] & 0xFFFFFF,
                reinterpret_cast<const std::uint32_t*>(data + y * stride)[x])
          << x << "," << y;
  cairo_surface_destroy(back);
  cairo_surface_destroy(s);
  fs::remove(path);
}

}  // namespace
}  // namespace fsi::raster_test
