// Rigid obstacles as signed distances (SPEC §9, contact.gap = "normal"): d(x) > 0
// outside the obstacle, the outward unit normal n(x) = ∇d(x) at the nearest point.
#pragma once

#include <cmath>
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

// A simple closed polygon (either orientation), grown by `margin` (SPEC §9): d = ± the
// distance to its nearest edge (negative inside, by the crossing-number test) minus
// the margin, n from the nearest boundary point towards x (away from x inside); on the
// boundary itself, the nearest edge's outward normal (the bisector at a corner).
//
// Why the margin: the zero level set of the polygon's own distance has corners, where
// n is not defined and turns with x (n = (x − c)/|x − c| about the corner c). A vertex
// resting on a corner is put on the tangent line by each QP, which turns the next
// normal by up to a right angle, and the passes cycle (measured: a beam over a block's
// corner stalled at a change of 1.4e-8 m after 200 passes; choosing instead the edge
// line the vertex is farthest outside of cycled between a wedge's two flanks, and both
// edge lines at once held a beam's end level with a block's top). The level set
// d = margin is the polygon's offset curve: its corners are arcs of radius margin, n is
// continuous on it, and the passes settle as for a disk. Measured (§7.1 beam, diam
// 0.06 m, pressed onto a block's corner and onto a wedge's tip, structure.h = 1 mm, the
// active-set solver): 3 passes for margins from 1e-6 to 1.7e-9 · diam, 17 at 1e-9 ·
// diam, none settling in 50 at 1e-11 · diam; max |u| moves by 2e-5 relative between
// 1e-6 and 1e-8 · diam, far below the discretisation's (5 % between h = 1 and 0.5 mm on
// the wedge). The runs use kPolygonMargin (solid/contact_gap.hpp).
class PolygonObstacle final : public Obstacle {
 public:
  PolygonObstacle(std::vector<Point> points, double margin);
  SignedDistance at(const Point& x) const override;

 private:
  struct Nearest {
    double distance = INFINITY;
    Point point = Point::Zero();
    std::size_t edge = 0;  // the edge the nearest point is on (i → i+1)
    double t = 0;          // its parameter on that edge
  };
  Nearest nearest_point(const Point& x) const;
  Point outward(std::size_t edge) const;
  bool inside(const Point& x) const;
  std::vector<Point> p_;
  bool ccw_;
  double margin_;
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
