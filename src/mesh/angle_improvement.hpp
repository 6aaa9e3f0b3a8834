// Raises the smallest angles of a triangulation: its interior edges flipped where that
// raises the smaller angle of the two triangles, and its vertices moved, each to
// where the smallest angle around it is largest (a local max-min search) — an
// interior vertex anywhere, a boundary vertex along its straight side.
// Only triangles under the target angle and their vertices are visited, so a mesh
// whose triangles are already good (a lattice's) costs one pass over it.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/planar_domain.hpp"

namespace fsi {

struct AngleImprovement {
  double target_deg = 45;  // triangles with a smaller angle are improved
  int rounds = 8;          // flips, then moves, this many times at most
  // A move makes no edge at the vertex longer than the longest there was, or than
  // max_edge_over_size · h(x) if `size` is given: the angles do not buy length.
  const SizeField* size = nullptr;
  double max_edge_over_size = 1.4;
};

struct AngleReport {
  int flips = 0, moves = 0;
};

// Where a vertex may go: nowhere (a corner, the end of a labelled piece, a point of a
// circle), anywhere (inside), or along the segment from a to b (to the point
// a + t (b − a), as the boundary's points were placed: they stay on the segment to
// round-off). A circle's points stay: sliding them lengthens chords, and the polygon
// strays from the circle by chord² / 8r (measured at hF = 0.02, r = 0.05: 1.75e-3 m
// against the cut's 0.96e-3).
struct Freedom {
  enum Kind { fixed, free, line } kind = free;
  Point a = Point::Zero(), b = Point::Zero();
};

// `triangles` counter-clockwise. No move or flip ever lowers the smallest angle of the
// triangles it touches, nor turns a triangle over; boundary edges are never flipped
// (they have one triangle).
AngleReport improve_angles(std::vector<Point>& vertices, std::vector<std::array<int, 3>>& triangles,
                           const std::vector<Freedom>& freedom,
                           const AngleImprovement& options = {});

// sin² of a triangle's smallest angle (−1 if it is not counter-clockwise): the measure
// every step compares, exact in rational operations.
double sine_squared_min_angle(const Point& a, const Point& b, const Point& c);

}  // namespace fsi
