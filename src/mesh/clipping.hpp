// The intersection of two triangles as a convex polygon (Sutherland–Hodgman), for
// the area-fraction χ and for integrating a fluid field exactly over a deformed
// structure triangle, piece by piece of the fluid mesh.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// subject ∩ clip, counter-clockwise; empty (or fewer than 3 points) if they meet in
// less than an area. Either triangle may be given clockwise.
std::vector<Point> clip_triangle(const std::array<Point, 3>& subject, const std::array<Point, 3>& clip);

// Area of a simple polygon (shoelace), ≥ 0.
double polygon_area(const std::vector<Point>& polygon);

inline double triangle_intersection_area(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  return polygon_area(clip_triangle(a, b));
}

}  // namespace fsi
