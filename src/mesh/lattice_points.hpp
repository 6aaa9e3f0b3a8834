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
// (h(x) where the rows fit the height exactly). Measured on the §7.2 box
// (docs/performance.md, "Meshing"): the smallest angle after the improvement is
// 42.3° at 0.4 and 43.0–43.1° from 0.5 to 0.7 at 150 000 triangles; at other sizes
// no value wins everywhere (0.7: 44.8° at hF = 0.01 but 40.4° at 0.02; 0.6: 40.1° and
// 43.0°). Under 0.5 a lattice row half a spacing off a side stays, and its triangles
// start as slivers.
inline constexpr double kLatticeClearance = 0.6;

// Points strictly inside the domain that `boundary` bounds (even-odd rule over its
// loops), none nearer a boundary segment than kLatticeClearance times the spacing.
std::vector<Point> lattice_points(const BoundarySegments& boundary, const SizeField& size);

}  // namespace fsi
