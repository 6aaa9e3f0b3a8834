#include "mesh/clipping.hpp"

#include <cmath>
#include <utility>

namespace fsi {

std::vector<Point> clip_triangle(const std::array<Point, 3>& subject, const std::array<Point, 3>& clip) {
  auto ccw = [](std::array<Point, 3> t) {
    const Point e1 = t[1] - t[0], e2 = t[2] - t[0];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(t[1], t[2]);
    return t;
  };
  const std::array<Point, 3> c = ccw(clip);
  const std::array<Point, 3> s = ccw(subject);
  std::vector<Point> poly(s.begin(), s.end()), next;
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    const Point p = c[k], q = c[(k + 1) % 3];
    auto side = [&](const Point& x) { return (q.x() - p.x()) * (x.y() - p.y()) - (q.y() - p.y()) * (x.x() - p.x()); };
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point& cur = poly[i];
      const Point& prev = poly[(i + poly.size() - 1) % poly.size()];
      const double sc = side(cur), sp = side(prev);
      if (sc >= 0) {
        if (sp < 0) next.push_back(prev + (cur - prev) * (sp / (sp - sc)));
        next.push_back(cur);
      } else if (sp >= 0) {
        next.push_back(prev + (cur - prev) * (sp / (sp - sc)));
      }
    }
    poly.swap(next);
  }
  return poly;
}

double polygon_area(const std::vector<Point>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& u = polygon[i];
    const Point& v = polygon[(i + 1) % polygon.size()];
    twice += u.x() * v.y() - u.y() * v.x();
  }
  return std::abs(0.5 * twice);
}

}  // namespace fsi
