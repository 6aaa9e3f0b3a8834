// Plane geometry of simple polygons (corners in order, either orientation), for the
// checks that a polygon obstacle fits the fluid box as a hole of D (SPEC §9): where
// it lies, how far it is from the box's sides and from the other holes, and whether a
// mesh's hole boundary lies on it. The contact's signed distance is solid's own
// (solid/signed_distance.hpp, with its margin).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// The shoelace formula: positive if counter-clockwise.
double signed_area(const std::vector<Point>& polygon);
// Crossing-number test (a point on the boundary may fall either way).
bool inside_polygon(const std::vector<Point>& polygon, const Point& x);
double distance_to_segment(const Point& x, const Point& a, const Point& b);
// The distance from x to the polygon's boundary (its edges).
double distance_to_boundary(const std::vector<Point>& polygon, const Point& x);
// Whether the closed segments ab and cd have a point in common.
bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d);
// The distance between the closed regions the two polygons bound: 0 if they meet
// (edges crossing, or one inside the other).
double polygon_distance(const std::vector<Point>& p, const std::vector<Point>& q);

}  // namespace fsi
