// P1 linear elasticity on the reference configuration Ω_S0 (SPEC §2). The dof
// numbering, components, mass matrix and loads are fem/vector_p1.hpp's.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/vector_p1.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

struct Lame {
  double lambda = 0, mu = 0;
  // λ = νE/((1+ν)(1−2ν)), μ = E/(2(1+ν)).
  static Lame from_young_poisson(double E, double nu);
};

// a_S(ψ_b e_d, ψ_a e_c) for basis functions with gradients ga = ∇ψ_a, gb = ∇ψ_b (P1's
// ∇λ, P2's ∇N): ε(ψ_a e_c):ε(ψ_b e_d) = ½(δ_cd ∇ψ_a·∇ψ_b + ∂_d ψ_a ∂_c ψ_b), div(ψ_a e_c) = ∂_c ψ_a.
inline double elasticity_entry(const Lame& lame, const Eigen::RowVector2d& ga, const Eigen::RowVector2d& gb, int c,
                               int d) {
  return lame.lambda * ga[c] * gb[d] + lame.mu * ((c == d ? ga.dot(gb) : 0.0) + ga[d] * gb[c]);
}

// A_S: (A_S)_ij = a_S(φ_j, φ_i) = ∫ λ div φ_j div φ_i + 2μ ε(φ_j):ε(φ_i).
// With Lame{0, μ_F} it is the matrix of ∫ 2μ_F ε(v):ε(w) used by eq. (33).
SparseMatrix assemble_elasticity(const Mesh& mesh, const Lame& lame);

// B (2nv × nv): B_{i,k} = ∫ (div φ_i) q_k, with q_k the scalar P1 basis; so
// −∫ (div w) p̃ = −(B p̃)·w for a P1 field p̃.
SparseMatrix assemble_divergence(const Mesh& mesh);

}  // namespace fsi
