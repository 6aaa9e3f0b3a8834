// The mesh generator of the shapes a case gives by numbers (the structure's
// rectangle, the fluid box and its holes): the boundary cut at the size h(x), a
// hexagonal lattice inside (mesh/lattice_points.hpp), their constrained Delaunay
// triangulation refined where the lattice leaves gaps (mesh/constrained_delaunay.hpp),
// then the smallest angles raised (mesh/angle_improvement.hpp).
//
// Why not Gmsh, which makes these meshes too: measured on the §7.2 box at 150 000
// triangles (docs/performance.md, "Meshing"), Gmsh's Frontal-Delaunay took 16 µs a
// triangle (Delaunay 6.6 µs without its smoothing), CGAL's Delaunay refinement alone
// 10 µs, this generator under 3 µs; its smallest angle is larger than Gmsh's (over
// 40° against 38°); and a run that needs no Gmsh does not load it (0.2 s).
#pragma once

#include "mesh/angle_improvement.hpp"
#include "mesh/mesh.hpp"
#include "mesh/planar_domain.hpp"

namespace fsi {

// What the generator did, for benchmarks and tests.
struct LatticeReport {
  int lattice_points = 0, refinement_points = 0;
  AngleReport angles;
};

// The triangles counter-clockwise; a boundary edge per boundary segment, labelled by
// its piece; every piece's ends are vertices. Deterministic: the same input gives
// the same mesh, bit for bit. Throws MeshError if the domain cannot be triangulated.
Mesh lattice_mesh(const PlanarDomain& domain, const SizeField& size,
                  LatticeReport* report = nullptr);

}  // namespace fsi
