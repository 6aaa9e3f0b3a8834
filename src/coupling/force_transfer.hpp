// The fluid force on the structure (paper eqs. 32–33, SPEC §4), small-displacement
// form: with ṽ = v_h∘φ and p̃ = p_h∘φ taken as P1 fields on the reference mesh,
//     F(w) = ∫ 2μ_F ε_X(ṽ):ε_X(w) − ∫ (div_X w) p̃ + (1/ε) ∫ ṽ·w − ∫ (f_F∘φ)·w,
// all integrals over Ω_S0. The first three are fixed matrices of the reference mesh
// (built once) applied to ṽ, p̃; the last is integrated at deformed positions.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "fluid/fluid_field.hpp"
#include "mesh/mesh.hpp"
#include "solid/elasticity.hpp"

namespace fsi {

// ṽ, p̃: the fluid fields at the deformed positions X_i + u(X_i) of the structure's
// vertices (outside D_h: at the nearest point of D_h).
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
  FluidForce(const Mesh& reference, double mu_F, double eps, const VectorField& f_F,
             ForceModel model = ForceModel::small);

  // The load vector of eq. (33)'s last four terms, for the sampled fields and the
  // displacement u defining φ.
  Eigen::VectorXd operator()(const SampledFluid& s, const Eigen::VectorXd& u) const;

 private:
  // −∫ (f_F∘φ)·w (times J if `jacobian`), φ(X) = X + u(X) at the quadrature points.
  Eigen::VectorXd body_force(const Eigen::VectorXd& u, bool jacobian = false) const;
  Eigen::VectorXd large(const SampledFluid& s, const Eigen::VectorXd& u) const;

  const Mesh& mesh_;
  double mu_F_;
  double eps_;
  ForceModel model_;
  VectorField f_F_;
  SparseMatrix K_mu_;  // ∫ 2μ_F ε(φ_j):ε(φ_i)
  SparseMatrix B_;     // ∫ (div φ_i) q_k
  SparseMatrix M_;     // ∫ φ_j·φ_i
};

}  // namespace fsi
