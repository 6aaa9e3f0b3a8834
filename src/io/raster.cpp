#include "io/raster.hpp"

#include <algorithm>
#include <cmath>

#include "io/colour.hpp"

namespace fsi {
namespace {

// viridis at 1024 levels, packed: finer than the 8-bit channels can show.
const std::array<std::uint32_t, 1024>& viridis_table() {
  static const std::array<std::uint32_t, 1024> table = [] {
    std::array<std::uint32_t, 1024> t{};
    for (int i = 0; i < 1024; ++i) {
      const Rgb c = viridis(i / 1023.0);
      const auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(255 * v)); };
      t[i] = byte(c[0]) << 16 | byte(c[1]) << 8 | byte(c[2]);
    }
    return t;
  }();
  return table;
}

double edge(const Point& a, const Point& b, double x, double y) {
  return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
}

}  // namespace

void paint_field(const PixelImage& image, const std::vector<Point>& at,
                 const std::vector<std::array<int, 3>>& triangles, const std::vector<double>& t01) {
  const auto& colour = viridis_table();
  const auto [cx0, cy0, cx1, cy1] = image.clip;
  for (const auto& tri : triangles) {
    std::array<int, 3> v = tri;
    const double area = edge(at[v[0]], at[v[1]], at[v[2]].x(), at[v[2]].y());
    if (area == 0 || !std::isfinite(area)) continue;
    if (area < 0) std::swap(v[1], v[2]);
    const Point &a = at[v[0]], &b = at[v[1]], &c = at[v[2]];
    const double scale = 1 / std::abs(area);
    const double f0 = t01[v[0]], f1 = t01[v[1]], f2 = t01[v[2]];
    // The pixels whose centres (x + 0.5, y + 0.5) may lie inside, within the clip.
    const int x0 =
        std::max(cx0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}) - 0.5)));
    const int x1 =
        std::min(cx1 - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}) - 0.5)));
    const int y0 =
        std::max(cy0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}) - 0.5)));
    const int y1 =
        std::min(cy1 - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}) - 0.5)));
    for (int y = y0; y <= y1; ++y) {
      auto* row = reinterpret_cast<std::uint32_t*>(reinterpret_cast<unsigned char*>(image.data) +
                                                   y * image.stride);
      for (int x = x0; x <= x1; ++x) {
        // Barycentric weights; a centre on an edge shared by two triangles is painted
        // by both with the same value (the field is continuous).
        const double w0 = edge(b, c, x + 0.5, y + 0.5), w1 = edge(c, a, x + 0.5, y + 0.5),
                     w2 = edge(a, b, x + 0.5, y + 0.5);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double t = std::clamp((w0 * f0 + w1 * f1 + w2 * f2) * scale, 0.0, 1.0);
        row[x] = colour[static_cast<std::size_t>(std::lround(1023 * t))];
      }
    }
  }
}

}  // namespace fsi
