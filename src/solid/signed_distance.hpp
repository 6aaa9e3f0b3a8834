// Rigid obstacles as signed distances (SPEC §9, contact.gap = "normal"): d(x) > 0
// outside the obstacle, the outward unit normal n(x) = ∇d(x) at the nearest point.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

struct SignedDistance {
  double d = 0;
  Point n = Point::Zero();
};

class Obstacle {
 public:
  virtual ~Obstacle() = default;
  virtual SignedDistance at(const Point& x) const = 0;
};

// The closed disk B(c, r): d = |x − c| − r, n = (x − c)/|x − c| (at the centre, where
// n is not defined, n = (0, 1): the point is deep inside, any direction will do).
class DiskObstacle final : public Obstacle {
 public:
  DiskObstacle(Point centre, double r) : c_(std::move(centre)), r_(r) {}
  SignedDistance at(const Point& x) const override;

 private:
  Point c_;
  double r_;
};

// Not reachable from a case yet ([[obstacles]] refuses polygons: the re-linearisation
// cycles at corners, solid/relinearised_contact.hpp); kept, tested, for that work.
// A simple closed polygon (either orientation): d = ± the distance to its nearest edge
// (negative inside, by the crossing-number test), n from the nearest boundary point
// towards x (away from x inside); on the boundary itself, the nearest edge's outward
// normal.
class PolygonObstacle final : public Obstacle {
 public:
  explicit PolygonObstacle(std::vector<Point> points);
  SignedDistance at(const Point& x) const override;

 private:
  bool inside(const Point& x) const;
  std::vector<Point> p_;
  bool ccw_;
};

// {x : (x − point)·n ≤ 0}, n the unit outward normal: d = (x − point)·n, n constant.
class HalfPlaneObstacle final : public Obstacle {
 public:
  HalfPlaneObstacle(Point point, Point normal) : point_(std::move(point)), n_(normal.normalized()) {}
  SignedDistance at(const Point& x) const override { return {(x - point_).dot(n_), n_}; }

 private:
  Point point_, n_;
};

// The nearest of several obstacles (the smallest d) and which one it is.
struct NearestObstacle {
  SignedDistance gap;
  int index = -1;
};
NearestObstacle nearest(const std::vector<const Obstacle*>& obstacles, const Point& x);

}  // namespace fsi
