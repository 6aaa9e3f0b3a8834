#include "mesh/lattice_points.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "mesh/mesh_error.hpp"
#include "mesh/polygon.hpp"

namespace fsi {
namespace {

// Row j at y0 + j dy holds the points x0 + (j odd ? dx/2 : 0) + i dx up to x1.
struct Lattice {
  double x0, y0, x1, dx, dy;
  int rows;
};

// Over [x0, x1] × [y0, y1] with no edge longer than h (as the boundary is cut): dx
// divides the width, the rows divide the height at most √3/2 dx apart. Beyond seven
// rows, an even number of them, so that the top row is unshifted like the bottom one:
// a box's bottom and top sides, cut at dx, are then rows of the lattice and their
// triangles equilateral (the one more row squeezes them by an eighth at most). A strip
// as high as h gets two rows, not one: P1 triangles one layer thick lock in bending
// (measured: the §7.2 beam at structure.h = H bent by half as much with one layer as
// with Gmsh's mesh).
Lattice fit_lattice(double x0, double y0, double x1, double y1, double h) {
  const double width = x1 - x0, height = y1 - y0;
  const double columns = std::max(1.0, std::ceil(width / h - 1e-9));
  const double dx = width / columns, ideal = dx * std::sqrt(3.0) / 2;
  if (height / ideal > 1e8 || columns > 1e8)
    throw MeshError("the lattice would need more than 1e8 rows or columns");
  int rows = std::max(2, static_cast<int>(std::ceil(height / ideal - 1e-9)));
  if (rows > 7) rows += rows % 2;
  return {x0, y0, x1, dx, height / rows, rows};
}

// The boundary segments within `reach` of each row, found once per lattice.
std::vector<std::vector<int>> segments_near_rows(const Lattice& l, const BoundarySegments& b,
                                                 double reach) {
  std::vector<std::vector<int>> near(l.rows + 1);
  for (int s = 0; s < static_cast<int>(b.segments.size()); ++s) {
    const Point &p = b.points[b.segments[s][0]], &q = b.points[b.segments[s][1]];
    const double lo = (std::min(p.y(), q.y()) - reach - l.y0) / l.dy,
                 hi = (std::max(p.y(), q.y()) + reach - l.y0) / l.dy;
    for (int j = std::max(0, static_cast<int>(std::ceil(lo)));
         j <= std::min(l.rows, static_cast<int>(std::floor(hi))); ++j)
      near[j].push_back(s);
  }
  return near;
}

// The lattice's points inside the domain (an odd number of crossings of the row to
// their left), in `zone`, and at least kLatticeClearance times the lattice's spacing
// from every boundary segment. The spacing: that of an equilateral lattice with these
// rows (dx where the rows are √3/2 dx apart), so that the first row above a side
// stays however close the rows of a thin strip are.
void add_points(const Lattice& l, const BoundarySegments& b,
                const std::function<bool(const Point&)>& zone, std::vector<Point>& out) {
  const double clearance = kLatticeClearance * 2 * l.dy / std::sqrt(3.0);
  const std::vector<std::vector<int>> near = segments_near_rows(l, b, clearance);
  std::vector<double> crossings;
  for (int j = 0; j <= l.rows; ++j) {
    const double y = l.y0 + j * l.dy;
    crossings.clear();
    for (int s : near[j]) {
      const Point &p = b.points[b.segments[s][0]], &q = b.points[b.segments[s][1]];
      if ((p.y() <= y) != (q.y() <= y))
        crossings.push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    std::size_t left = 0;
    for (double i = 0;; ++i) {
      const Point x(l.x0 + (j % 2 ? l.dx / 2 : 0) + i * l.dx, y);
      if (x.x() > l.x1) break;
      while (left < crossings.size() && crossings[left] < x.x()) ++left;
      if (left % 2 == 0 || !zone(x)) continue;
      const bool clear = std::all_of(near[j].begin(), near[j].end(), [&](int s) {
        return distance_to_segment(x, b.points[b.segments[s][0]], b.points[b.segments[s][1]]) >=
               clearance;
      });
      if (clear) out.push_back(x);
    }
  }
}

}  // namespace

std::vector<Point> lattice_points(const BoundarySegments& boundary, const SizeField& size) {
  // The outer loop's extent: the lattice's.
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (int s = boundary.loop_begin[0]; s < boundary.loop_begin[1]; ++s) {
    const Point& p = boundary.points[boundary.segments[s][0]];
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()),
    y1 = std::max(y1, p.y());
  }
  std::vector<Point> out;
  if (size.uniform()) {
    add_points(
        fit_lattice(x0, y0, x1, y1, size.h), boundary, [](const Point&) { return true; }, out);
    return out;
  }
  // Where h(x) = h: beyond the transition; where h(x) = h_near: in the band.
  const double transition = (size.h - size.h_near) / size.growth;
  add_points(
      fit_lattice(x0, y0, x1, y1, size.h), boundary,
      [&](const Point& x) { return size.distance_to_band(x) >= transition; }, out);
  const double bx0 = std::max(x0, size.band[0]), by0 = std::max(y0, size.band[1]),
               bx1 = std::min(x1, size.band[2]), by1 = std::min(y1, size.band[3]);
  if (bx1 > bx0 && by1 > by0)
    add_points(
        fit_lattice(bx0, by0, bx1, by1, size.h_near), boundary,
        [&](const Point& x) { return size.distance_to_band(x) == 0; }, out);
  return out;
}

}  // namespace fsi
