// The structure's mass matrix ρ_S ∫ φ_j·φ_i for Newmark's step (SPEC §12): consistent
// (P1 or P2), or with the contact nodes' mass redistributed to the nodes next to them
// (the mass-redistribution method of Khenous, Laborde & Renard, Eur. J. Mech. A/Solids
// 27, 2008), so that a contact node carries no inertia and the contact condition at
// t^{n+1} does not make the impact gain or lose energy through those nodes' velocity.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "fem/p2.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

using SparseMatrix = Eigen::SparseMatrix<double>;

// ρ ∫ φ_j·φ_i on P1 (p2 null) or on the P2 space (exact: degree 4), dofs c·n + node.
SparseMatrix consistent_mass(const Mesh& mesh, const P2Space* p2, double rho);

// P1 only. The row-sum lumped mass (ρ|T|/3 to each vertex of T), then each vertex of
// `massless` gives its mass in equal parts to its neighbours (vertices sharing a
// triangle) that are not massless, or, if it has none, to the nearest vertex that is
// not. Diagonal, total mass kept exactly; the centre of mass moves by O(h) times the
// boundary's share of the mass, O(h²). Khenous et al. also keep the centre of mass
// and the moments of inertia, by a global least-squares fit; for P1 their paper's
// numerical results use the same idea (no mass on the contact boundary), and the
// bar-impact test measures what this one gives (docs/validation.md, "Bar impact").
// std::invalid_argument if every vertex is massless.
SparseMatrix redistributed_mass(const Mesh& mesh, const std::vector<int>& massless, double rho);

}  // namespace fsi
