// What the mesh generator (mesh/lattice_mesher.hpp) triangulates: a plane region
// bounded by closed loops of labelled pieces — straight segments and full circles —
// and the size h(x) its triangles should have; and the boundary cut into segments
// of that size, the constrained edges of the triangulation.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// A segment from a to b, or (r > 0) the full circle of centre c and radius r, from
// the angle 0, counter-clockwise. Cut into at least min_segments segments.
struct BoundaryPiece {
  Point a = Point::Zero(), b = Point::Zero();
  Point c = Point::Zero();
  double r = 0;
  int label = 0;  // index into PlanarDomain::labels
  int min_segments = 1;
  bool slide = true;  // may its points slide along it when the angles are improved

  bool circle() const { return r > 0; }
  double length() const;
  Point at(double t) const;  // t in [0, 1]
};

// loops[0] is the outer boundary; the others bound holes. A loop's pieces follow one
// another (each starts where the one before ends); a circle is a loop of its own.
struct PlanarDomain {
  std::vector<std::vector<BoundaryPiece>> loops;
  std::vector<std::string> labels;  // the Mesh's label names, in this order
};

// h(x): h everywhere, or (band refinement) h_near inside the box `band` = [x_min,
// y_min, x_max, y_max] growing by `growth` per unit of distance from it, up to h.
struct SizeField {
  double h = 0;
  double h_near = 0;
  std::array<double, 4> band{};
  double growth = 0.2;

  bool uniform() const { return !(h_near > 0 && h_near < h); }
  double distance_to_band(const Point& x) const;
  double operator()(const Point& x) const;
};

// The boundary cut into segments no longer than h(x) (the number of segments of a
// piece from the integral of 1/h along it; equal lengths where h is uniform).
// Points are shared between consecutive pieces: a loop of n segments has n points.
struct BoundarySegments {
  std::vector<Point> points;
  std::vector<std::array<int, 2>>
      segments;            // in loop order, each loop counter-clockwise or not as given
  std::vector<int> piece;  // per segment: the index of its piece in pieces()
  std::vector<const BoundaryPiece*> pieces;  // all loops' pieces, in order
  std::vector<int> loop_begin;               // first segment of each loop, and the total at the end
};
BoundarySegments cut_boundary(const PlanarDomain& domain, const SizeField& size);

// The distance from x to a piece (to its circle or its segment).
double distance_to_piece(const BoundaryPiece& piece, const Point& x);

}  // namespace fsi
