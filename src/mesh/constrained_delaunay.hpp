// The constrained Delaunay triangulation of a boundary and interior points, refined
// (Delaunay refinement: Chew and Ruppert, as CGAL's 2D mesher does it) until no
// triangle inside has an angle under 20.7° or an edge longer than a multiple of the
// size h(x) at its centroid. CGAL does what needs exact predicates (the triangulation, the
// constraints, the refinement that keeps it Delaunay); mesh/lattice_mesher.hpp
// chooses the points and improves the result.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/planar_domain.hpp"

namespace fsi {

struct DelaunayInput {
  std::vector<Point> boundary;               // the constrained segments' points
  std::vector<std::array<int, 2>> segments;  // indices into `boundary`; closed loops
  std::vector<Point> interior;               // points strictly inside the domain
};

struct DelaunayMesh {
  // The boundary points first, with their indices; then the interior points and
  // those the refinement added (on the segments too).
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise, the domain's only
  // The constrained edges: the input segments, or pieces of them where the
  // refinement split one.
  std::vector<std::array<int, 2>> boundary_edges;
};

// The domain is what lies inside an odd number of loops (the outer boundary minus
// the holes). Throws MeshError if CGAL fails (an input it refuses, such as
// crossing segments).
DelaunayMesh constrained_delaunay(const DelaunayInput& input, const SizeField& size,
                                  double max_edge_over_size);

}  // namespace fsi
