// The interior points of a generated mesh: hexagonal lattices (rows of spacing dx,
// every other row shifted by dx/2, rows √3/2 dx apart), whose Delaunay triangles are
// equilateral, laid where the size h(x) is constant — everywhere for a uniform size;
// inside the band and beyond its transition for a band refinement (Delaunay
// refinement fills the transition). Points nearer the boundary than a fraction of
// h(x) are left out: the boundary's own points and the improvement of angles
// (mesh/angle_improvement.hpp) make the layer along it.
#pragma once

#include <vector>

#include "mesh/planar_domain.hpp"

namespace fsi {

// How near the boundary a lattice point may be, in units of the lattice's spacing
// (h(x) where the rows fit the height exactly). 0.6: measured on the §7.2 box
// (docs/performance.md, "Meshing"), the smallest angle after the improvement is
// highest between 0.55 and 0.6, and 0.6 leaves no gap wider than a triangle.
inline constexpr double kLatticeClearance = 0.6;

// Points strictly inside the domain that `boundary` bounds (even-odd rule over its
// loops), none nearer a boundary segment than kLatticeClearance times the spacing.
std::vector<Point> lattice_points(const BoundarySegments& boundary, const SizeField& size);

}  // namespace fsi
