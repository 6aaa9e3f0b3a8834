// The non-penetration constraint by signed distance (SPEC §9, contact.gap = "normal"),
// linearised about the deformed position x_k = X + u_k:
//     d(x_k) + n(x_k)·(u − u_k) ≥ 0   on the candidate boundary,
// imposed weakly as eq. (15): (C)_ij = ∫ n(x_k(X))·φ_j φ_i ds, (c_lb)_i = ∫ (n·u_k − d) φ_i ds,
// the integrals by the trapezoidal rule on each candidate edge. That rule makes row i
// the constraint at vertex i times its weight (half its edges' lengths): the discrete
// non-penetration then holds at every candidate vertex once the linearisation has
// converged, which is what the stopping test of SPEC §9 checks. (With the consistent
// integrals of eq. 15 a P1 gap g with ∫ g φ_i ≥ 0 for every i may still be negative at
// a vertex next to the contact zone's end.)
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solid/contact.hpp"
#include "solid/signed_distance.hpp"

namespace fsi {

// The candidate vertices and their weights: `boundary` = "Gamma_C", the vertices
// strictly inside Γ_C (its ends carry no row, as eq. 15's); "all", every vertex of a
// boundary edge not on Γ_D. Weights: half the reference lengths of the candidate
// edges at the vertex.
struct CandidateSet {
  std::vector<int> vertices;
  std::vector<double> weights;
};
CandidateSet candidate_vertices(const Mesh& mesh, const std::string& boundary, int gamma_c, int gamma_d);

// C_S, c_lb at u_k (2nv, paper ordering).
ContactConstraint assemble_normal_contact(const Mesh& mesh, const CandidateSet& candidates,
                                          const std::vector<const Obstacle*>& obstacles, const Eigen::VectorXd& u_k);

// min over the candidates of the exact d(X + u): the smallest gap, negative where the
// structure penetrates an obstacle.
double min_exact_gap(const Mesh& mesh, const CandidateSet& candidates, const std::vector<const Obstacle*>& obstacles,
                     const Eigen::VectorXd& u);

}  // namespace fsi
