#include "solid/signed_distance.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/polygon.hpp"

namespace fsi {

SignedDistance DiskObstacle::at(const Point& x) const {
  const Point v = x - c_;
  const double rho = v.norm();
  SignedDistance s;
  s.d = rho - r_;
  s.n = rho > 0 ? Point(v / rho) : Point(0, 1);
  return s;
}

PolygonObstacle::PolygonObstacle(std::vector<Point> points, double margin) : p_(std::move(points)), margin_(margin) {
  double area = 0;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Point &a = p_[i], &b = p_[(i + 1) % p_.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  ccw_ = area > 0;
}

bool PolygonObstacle::inside(const Point& x) const { return inside_polygon(p_, x); }

Point PolygonObstacle::outward(std::size_t i) const {  // edge i → i+1: right of it if counter-clockwise
  const Point e = p_[(i + 1) % p_.size()] - p_[i];
  return Point(ccw_ ? Point(e.y(), -e.x()) : Point(-e.y(), e.x())).normalized();
}

PolygonObstacle::Nearest PolygonObstacle::nearest_point(const Point& x) const {
  Nearest best;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const Point &a = p_[i], e = p_[(i + 1) % p_.size()] - a;
    const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Point q = a + t * e;
    const double dist = (x - q).norm();
    if (dist < best.distance) best = {dist, q, i, t};
  }
  return best;
}

SignedDistance PolygonObstacle::at(const Point& x) const {
  const std::size_t n = p_.size();
  const Nearest q = nearest_point(x);
  SignedDistance s;
  const bool in = inside(x);
  s.d = (in ? -q.distance : q.distance) - margin_;
  if (q.distance > 0) {
    s.n = in ? Point((q.point - x) / q.distance) : Point((x - q.point) / q.distance);
  } else if (q.t == 0 || q.t == 1) {
    // On a corner the normal is not defined: the bisector of its two edges'.
    const std::size_t other = q.t == 0 ? (q.edge + n - 1) % n : (q.edge + 1) % n;
    s.n = (outward(q.edge) + outward(other)).normalized();
  } else {
    s.n = outward(q.edge);
  }
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
