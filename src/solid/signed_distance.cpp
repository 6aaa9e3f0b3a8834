#include "solid/signed_distance.hpp"

#include <algorithm>
#include <cmath>

namespace fsi {

SignedDistance DiskObstacle::at(const Point& x) const {
  const Point v = x - c_;
  const double rho = v.norm();
  SignedDistance s;
  s.d = rho - r_;
  s.n = rho > 0 ? Point(v / rho) : Point(0, 1);
  return s;
}

PolygonObstacle::PolygonObstacle(std::vector<Point> points) : p_(std::move(points)) {
  double area = 0;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Point &a = p_[i], &b = p_[(i + 1) % p_.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  ccw_ = area > 0;
}

bool PolygonObstacle::inside(const Point& x) const {
  bool in = false;
  for (std::size_t i = 0, j = p_.size() - 1; i < p_.size(); j = i++) {
    const Point &a = p_[i], &b = p_[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

SignedDistance PolygonObstacle::at(const Point& x) const {
  const std::size_t n = p_.size();
  auto outward = [&](std::size_t i) {  // edge i → i+1: right of it if counter-clockwise
    const Point e = p_[(i + 1) % n] - p_[i];
    return Point(ccw_ ? Point(e.y(), -e.x()) : Point(-e.y(), e.x())).normalized();
  };
  double best = INFINITY;
  Point closest = p_[0], edge_normal(0, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = p_[i], &b = p_[(i + 1) % n];
    const Point e = b - a;
    const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Point q = a + t * e;
    const double dist = (x - q).norm();
    if (dist < best) {
      best = dist, closest = q;
      // On a corner the normal is not defined: the bisector of its two edges' (a
      // structure vertex resting on the corner would otherwise take one edge's normal
      // or the other's from one linearisation to the next, and never settle).
      if (t == 0) edge_normal = (outward(i) + outward((i + n - 1) % n)).normalized();
      else if (t == 1) edge_normal = (outward(i) + outward((i + 1) % n)).normalized();
      else edge_normal = outward(i);
    }
  }
  SignedDistance s;
  const bool in = inside(x);
  s.d = in ? -best : best;
  if (best > 0) s.n = in ? Point((closest - x) / best) : Point((x - closest) / best);
  else s.n = edge_normal;
  return s;
}

NearestObstacle nearest(const std::vector<const Obstacle*>& obstacles, const Point& x) {
  NearestObstacle out;
  out.gap.d = INFINITY;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const SignedDistance s = obstacles[i]->at(x);
    if (s.d < out.gap.d) out.gap = s, out.index = static_cast<int>(i);
  }
  return out;
}

}  // namespace fsi
