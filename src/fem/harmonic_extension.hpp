// Moves a triangulation with its boundary: the displacement d given on the boundary
// vertices is extended inside by the discrete harmonic extension (P1 Laplace,
// −div(k ∇d) = 0, d given on the boundary), with k = 1/|T| so that small triangles,
// next to the moving boundary, move nearly rigidly and keep their shape. Used by the
// body-fitted fluid (coupling/body_fitted_fluid.hpp) to follow small moves of the
// structure without remeshing: a fresh Gmsh mesh is a discontinuous function of the
// boundary, a moved one a smooth function.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <memory>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

class HarmonicExtension {
 public:
  // Factorises the Laplacian on the interior vertices of `mesh` (those on no
  // boundary edge); the mesh is copied.
  explicit HarmonicExtension(const Mesh& mesh);

  // The mesh moved by d: `boundary_d` per vertex (only boundary vertices' entries are
  // read), extended inside. The triangles keep their vertices.
  Mesh moved(const std::vector<Point>& boundary_d) const;

  const Mesh& mesh() const { return mesh_; }

 private:
  Mesh mesh_;
  std::vector<int> interior_index_;   // vertex → interior unknown, −1 on the boundary
  Eigen::SparseMatrix<double> A_IB_;  // interior rows, boundary columns (by vertex)
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> A_II_;
};

// The smallest interior angle of any triangle, degrees (negative area: −1).
double min_angle_deg(const Mesh& mesh);

}  // namespace fsi
