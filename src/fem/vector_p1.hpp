// Vector-valued P1 fields on a mesh, the vocabulary the structure, the fluid's force
// and the coupling share (issue 28): the paper's dof numbering φ_i = (φ_i, 0),
// φ_{nv+i} = (0, φ_i), so dof(i, c) = c·nv + i; a dof vector's two components; the
// vector mass matrix; volume and surface loads of a vector field.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

using SparseMatrix = Eigen::SparseMatrix<double>;
using VectorField = std::function<Point(const Point&)>;

inline int dof(int vertex, int component, int num_vertices) {
  return component * num_vertices + vertex;
}

// Both components of each of `nodes` (n nodes in all), sorted: a clamped side's dofs.
std::vector<int> both_components(const std::vector<int>& nodes, int n);

// Split a dof vector into its two components (length nv each).
Eigen::VectorXd component(const Eigen::VectorXd& u, int c);

// Vector mass matrix: ∫ φ_j · φ_i.
SparseMatrix assemble_vector_mass(const Mesh& mesh);

// ∫_{Ω} f · φ_i, by a quadrature rule exact to `degree` on each triangle.
Eigen::VectorXd assemble_volume_load(const Mesh& mesh, const VectorField& f, int degree = 4);

// ∫_{edges labelled `label`} h · φ_i ds, by `points`-point Gauss on each edge.
Eigen::VectorXd assemble_surface_load(const Mesh& mesh, int label, const VectorField& h,
                                      int points = 3);

}  // namespace fsi
