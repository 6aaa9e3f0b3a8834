#include "mesh/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace fsi {

double signed_area(const std::vector<Point>& p) {
  double twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point &a = p[i], &b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return twice / 2;
}

bool inside_polygon(const std::vector<Point>& p, const Point& x) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Point &a = p[i], &b = p[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

double distance_to_segment(const Point& x, const Point& a, const Point& b) {
  const Point e = b - a;
  const double t = e.squaredNorm() > 0 ? std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
  return (x - (a + t * e)).norm();
}

double distance_to_boundary(const std::vector<Point>& p, const Point& x) {
  double d = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) d = std::min(d, distance_to_segment(x, p[i], p[(i + 1) % p.size()]));
  return d;
}

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  auto side = [](const Point& p, const Point& q, const Point& r) {
    const double s = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    return (s > 0) - (s < 0);
  };
  const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
  if (s1 != s2 && s3 != s4) return true;
  auto within = [](const Point& p, const Point& q, const Point& r) {  // r on segment pq, given collinear
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) || (s3 == 0 && within(c, d, a)) ||
         (s4 == 0 && within(c, d, b));
}

double polygon_distance(const std::vector<Point>& p, const std::vector<Point>& q) {
  if (inside_polygon(p, q.front()) || inside_polygon(q, p.front())) return 0;
  double d = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Point &a = p[i], &b = p[(i + 1) % p.size()], &c = q[j], &e = q[(j + 1) % q.size()];
      if (segments_cross(a, b, c, e)) return 0;
      // Apart, the nearest points of two segments include an end of one of them.
      d = std::min({d, distance_to_segment(a, c, e), distance_to_segment(b, c, e), distance_to_segment(c, a, b),
                    distance_to_segment(e, a, b)});
    }
  return d;
}

}  // namespace fsi
