// The fluid force on the structure (paper eqs. 32–33, SPEC §4), small-displacement
// form: with ṽ = v_h∘φ and p̃ = p_h∘φ taken as P1 fields on the reference mesh,
//     F(w) = ∫ 2μ_F ε_X(ṽ):ε_X(w) − ∫ (div_X w) p̃ + (1/ε) ∫ ṽ·w − ∫ (f_F∘φ)·w,
// all integrals over Ω_S0. The first three are fixed matrices of the reference mesh
// (built once) applied to ṽ, p̃; the last is integrated at deformed positions.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "fem/p2.hpp"
#include "fem/uniform_refinement.hpp"
#include "fluid/fluid_field.hpp"
#include "mesh/mesh.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

// ṽ, p̃: the fluid fields at the deformed positions X_i + u(X_i) of the structure's
// vertices (outside D_h: at the nearest point of D_h).
// For the P2 structure (structure.element = "P2"): at its n nodes, v 2n, p n.
struct SampledFluid {
  Eigen::VectorXd v;  // 2nv, paper ordering
  Eigen::VectorXd p;  // nv
};
SampledFluid sample_at_deformed_vertices(const FluidField& field, const Mesh& reference,
                                         const Eigen::VectorXd& u);
// The same in two steps: where the deformed vertices lie in the fluid mesh (the
// triangles a fluid solve must be exact on), then the fields there.
std::vector<Location> locate_deformed_vertices(const PointLocator& fluid, const Mesh& reference,
                                               const Eigen::VectorXd& u);
std::vector<int> triangles_of(const std::vector<Location>& where);
SampledFluid sample_at(const FluidField& field, const std::vector<Location>& where);

// coupling.force (SPEC §11): "small" is eq. (33) above; "large" the exact pull-back
// of §5 before eq. (32),
//     F(w) = ∫ J (σ_F∘φ) F⁻ᵀ : ∇_X w + (1/ε) ∫ J ṽ·w − ∫ J (f_F∘φ)·w,
// σ_F = −p̃ I + 2μ_F sym(∇_X ṽ F⁻¹), F = I + ∇_X u, J = det F (large_force.cpp).
enum class ForceModel { small, large };

class FluidForce {
 public:
  // `sampling` = m > 1 (coupling.force_sampling, P1 only): the integrals run on the
  // reference mesh cut into m² triangles each (fem/uniform_refinement.hpp), the fluid
  // sampled at its vertices (sample_mesh(), at to_samples(u)), the load restricted to
  // the structure's vertices with the transpose of the interpolation.
  FluidForce(const Mesh& reference, double mu_F, double eps, const VectorField& f_F,
             ForceModel model = ForceModel::small, int sampling = 1);
  // The same on the P2 space (issue 14, p2_force.cpp): ṽ, p̃ and u P2 fields on the
  // space's nodes, dof(node, c) = c·n + node, w over the P2 basis. `space` must
  // outlive the object.
  FluidForce(const P2Space& space, double mu_F, double eps, const VectorField& f_F,
             ForceModel model = ForceModel::small);
  FluidForce(const P2Space&& space, double mu_F, double eps, const VectorField& f_F,
             ForceModel model = ForceModel::small) = delete;

  // The load vector of eq. (33)'s last four terms, for the sampled fields and the
  // displacement u defining φ. Throws std::invalid_argument if a size does not match
  // the space (2n, n, 2n; n the vertices for P1, the nodes for P2).
  Eigen::VectorXd operator()(const SampledFluid& s, const Eigen::VectorXd& u) const;

  // Where the fluid is sampled: the vertices of this mesh displaced by to_samples(u)
  // (the reference mesh and u itself unless sampling > 1; a P2 space's nodal mesh).
  const Mesh& sample_mesh() const { return space_ ? *nodes_ : mesh_; }
  Eigen::VectorXd to_samples(const Eigen::VectorXd& u) const;

 private:
  // −∫ (f_F∘φ)·w (times J if `jacobian`), φ(X) = X + u(X) at the quadrature points.
  Eigen::VectorXd body_force(const Eigen::VectorXd& u, bool jacobian = false) const;
  Eigen::VectorXd large(const SampledFluid& s, const Eigen::VectorXd& u) const;
  // The P2 forms (p2_force.cpp).
  Eigen::VectorXd p2_body_force(const Eigen::VectorXd& u) const;
  Eigen::VectorXd p2_large(const SampledFluid& s, const Eigen::VectorXd& u) const;

  std::shared_ptr<const UniformRefinement> refinement_;  // sampling > 1 only
  const Mesh& mesh_;  // the integrals' mesh: the reference, or its refinement
  std::shared_ptr<const Mesh> nodes_;  // P2: the space's nodal mesh (where the fields are sampled)
  const P2Space* space_ = nullptr;  // set for the P2 structure
  double mu_F_;
  double eps_;
  ForceModel model_;
  VectorField f_F_;
  SparseMatrix K_mu_;  // ∫ 2μ_F ε(φ_j):ε(φ_i)
  SparseMatrix B_;     // ∫ (div φ_i) q_k (q_k: P1, or P2 for the P2 space)
  SparseMatrix M_;     // ∫ φ_j·φ_i
};

}  // namespace fsi
