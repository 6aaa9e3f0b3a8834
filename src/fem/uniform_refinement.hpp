// A mesh's triangles each cut into m² similar ones, and the P1 interpolation from the
// mesh to its refinement (coupling.force_sampling, issue 27). The force of eq. (33)
// samples v∘φ at the structure's vertices and integrates the P1 interpolant of those
// samples: across a Brinkman layer thinner than the structure's triangles the
// interpolant misses the layer, an O(1) error at a fixed ratio of layer to mesh
// (docs/validation.md, "The penalty's error"). Sampling at the vertices of the
// refinement, and restricting the integrals with the transpose, resolves it while
// the structure keeps its own mesh.
#pragma once

#include <Eigen/SparseCore>

#include "mesh/mesh.hpp"

namespace fsi {

struct UniformRefinement {
  Mesh fine;  // vertices and triangles only (no boundary edges)
  // P1 interpolation, fine vertex values = P · coarse vertex values (one component).
  Eigen::SparseMatrix<double> P;
};

// m ≥ 1; m = 1 gives the mesh itself and the identity.
UniformRefinement refine_uniformly(const Mesh& mesh, int m);

}  // namespace fsi
