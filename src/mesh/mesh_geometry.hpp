// What a generated mesh is made from: the structure's rectangle and the fluid box with
// its holes and band, as numbers (mesh/generated_mesh.hpp's generator and
// mesh/gmsh_io.hpp's Gmsh both read them).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <numbers>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// Ω_S0 = (0,L)×(0,H); boundary labels Gamma_D (x = 0), Gamma_C ((xc_min,xc_max)
// on y = 0, with vertices exactly at both ends), Gamma_N (the rest).
struct StructureGeometry {
  double L, H, xc_min, xc_max;
  double h;  // target element size
};

// A hole of D: the disk B((x0, y0), r), or the polygon `corners` (a simple one, either
// orientation) if it has any. A polygon's boundary is a loop of mesh edges through its
// corners, each side cut into at least two.
struct FluidHole {
  double x0 = 0, y0 = 0, r = 0;
  std::vector<Point> corners = {};
};

// The length of a hole's boundary: the circle of radius r, or the closed polygon
// `corners` if it has any (the refinement at the holes, its sampling and its estimate).
inline double hole_perimeter(double r, const std::vector<Point>& corners) {
  if (corners.empty()) return 2 * std::numbers::pi * r;
  double length = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) length += (corners[(i + 1) % corners.size()] - corners[i]).norm();
  return length;
}

// D = (0,L1)×(−H2,H1) minus the disk B((x0,y0),r) (or minus `holes`); labels Sigma_1
// (left), Sigma_2 (bottom), Sigma_3 (right), Sigma_4 (top), Sigma_5 (circle; or
// Sigma_5_1, Sigma_5_2, ... the holes).
//
// With h_near > 0, triangles of size h_near inside the box `band` ([x_min, y_min,
// x_max, y_max]), growing linearly by kBandGrowth per unit distance from it up to h:
// the band refinement of fluid.h_near.
struct FluidGeometry {
  double L1, H1, H2, x0, y0, r;
  double h;
  double h_near = 0;
  std::array<double, 4> band{};
  double h_holes = 0;  // the size on the holes' boundaries, growing by kBandGrowth (Gmsh only); 0: none
  // [[obstacles]] (SPEC §9): these disks and polygons, any number, are D's holes
  // instead of the one above, labelled Sigma_5_1, Sigma_5_2, ... in this order.
  std::optional<std::vector<FluidHole>> holes = std::nullopt;
};

// The size's growth away from the band, per unit length. Measured on §7.2 (docs/
// validation.md, "Band refinement"): halving it or the far size h moves max |u| by
// under 0.5 µm at h_near = 0.001, while the triangle count stays within 10 % of the
// band's own.
inline constexpr double kBandGrowth = 0.2;

// Generators' tolerances are absolute in places (Gmsh's: the §7.1 beam scaled by 1e20
// or 1e-100 made it throw, measured), and squared lengths overflow far from 1: a
// geometry is meshed in units of a power of two near its extent, exact to divide and
// multiply by (the vertices stay exactly at the ends of Γ_C). Within [2^-8, 2^8] the
// unit is 1: the lengths as given.
double reference_length(double extent);

}  // namespace fsi
