// P1 linear elasticity on the reference configuration Ω_S0 (SPEC §2).
// Degrees of freedom follow the paper: φ_i = (φ_i, 0), φ_{nv+i} = (0, φ_i), so
// dof(i, c) = c·nv + i.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

using SparseMatrix = Eigen::SparseMatrix<double>;
using VectorField = std::function<Point(const Point&)>;

struct Lame {
  double lambda = 0, mu = 0;
  // λ = νE/((1+ν)(1−2ν)), μ = E/(2(1+ν)).
  static Lame from_young_poisson(double E, double nu);
};

inline int dof(int vertex, int component, int num_vertices) {
  return component * num_vertices + vertex;
}

// Both components of each of `nodes` (n nodes in all), sorted: a clamped side's dofs.
std::vector<int> both_components(const std::vector<int>& nodes, int n);

// a_S(ψ_b e_d, ψ_a e_c) for basis functions with gradients ga = ∇ψ_a, gb = ∇ψ_b (P1's
// ∇λ, P2's ∇N): ε(ψ_a e_c):ε(ψ_b e_d) = ½(δ_cd ∇ψ_a·∇ψ_b + ∂_d ψ_a ∂_c ψ_b), div(ψ_a e_c) = ∂_c ψ_a.
inline double elasticity_entry(const Lame& lame, const Eigen::RowVector2d& ga, const Eigen::RowVector2d& gb, int c,
                               int d) {
  return lame.lambda * ga[c] * gb[d] + lame.mu * ((c == d ? ga.dot(gb) : 0.0) + ga[d] * gb[c]);
}

// A_S: (A_S)_ij = a_S(φ_j, φ_i) = ∫ λ div φ_j div φ_i + 2μ ε(φ_j):ε(φ_i).
// With Lame{0, μ_F} it is the matrix of ∫ 2μ_F ε(v):ε(w) used by eq. (33).
SparseMatrix assemble_elasticity(const Mesh& mesh, const Lame& lame);

// Vector mass matrix: ∫ φ_j · φ_i.
SparseMatrix assemble_vector_mass(const Mesh& mesh);

// B (2nv × nv): B_{i,k} = ∫ (div φ_i) q_k, with q_k the scalar P1 basis; so
// −∫ (div w) p̃ = −(B p̃)·w for a P1 field p̃.
SparseMatrix assemble_divergence(const Mesh& mesh);

// ∫_{Ω} f · φ_i, by a quadrature rule exact to `degree` on each triangle.
Eigen::VectorXd assemble_volume_load(const Mesh& mesh, const VectorField& f, int degree = 4);

// ∫_{edges labelled `label`} h · φ_i ds, by `points`-point Gauss on each edge.
Eigen::VectorXd assemble_surface_load(const Mesh& mesh, int label, const VectorField& h,
                                      int points = 3);

// Split a dof vector into its two components (length nv each).
Eigen::VectorXd component(const Eigen::VectorXd& u, int c);

}  // namespace fsi
