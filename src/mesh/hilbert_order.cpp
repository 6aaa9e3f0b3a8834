#include "mesh/hilbert_order.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace fsi {

// The classic iterative form (Hamilton, "Compact Hilbert indices", 2006; the same as
// Wikipedia's xy2d): at each scale, the quadrant's index, then the sub-square rotated
// so that the curve enters and leaves it where its neighbours join.
unsigned long long hilbert_index(unsigned x, unsigned y, int bits) {
  const unsigned n = 1u << bits;
  unsigned long long d = 0;
  for (unsigned s = n / 2; s > 0; s /= 2) {
    const unsigned rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<unsigned long long>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant (only the bits below s are read from now on)
      if (rx == 1) x = n - 1 - x, y = n - 1 - y;
      std::swap(x, y);
    }
  }
  return d;
}

std::vector<int> hilbert_order(const std::vector<Point>& points) {
  constexpr int kBits = 16;
  constexpr double kCells = (1u << kBits) - 1;
  Point low = Point::Constant(0), high = Point::Constant(0);
  if (!points.empty()) {
    low = high = points.front();
    for (const Point& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  }
  const double extent = (high - low).maxCoeff();  // one scale for both axes: a square's cells
  const double scale = extent > 0 ? kCells / extent : 0.0;
  std::vector<std::pair<unsigned long long, int>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point c = (points[i] - low) * scale;
    keyed[i] = {hilbert_index(static_cast<unsigned>(c.x()), static_cast<unsigned>(c.y()), kBits), static_cast<int>(i)};
  }
  std::sort(keyed.begin(), keyed.end());  // ties by index: stable
  std::vector<int> order(points.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace fsi
