// Hyperelastic plane-strain materials (SPEC §11) on P1 triangles of the reference
// configuration Ω_S0: the first Piola–Kirchhoff stress P(F), its derivative, the
// internal force f_int(u)_i = ∫ P(F(u)) : ∇φ_i and the tangent K_T(u) = ∂f_int/∂u.
// F = I + ∇u is constant on a P1 triangle, so one point per triangle integrates both
// exactly. At u = 0 both models' tangents are A_S (the linear model's matrix, same λ
// and μ): small displacements recover eq. (16).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <array>
#include <string>

#include "fem/p1.hpp"
#include "mesh/mesh.hpp"
#include "solid/elasticity.hpp"

namespace fsi {

using Matrix2 = Eigen::Matrix2d;

enum class MaterialModel { linear, saint_venant_kirchhoff, neo_hookean };
// "linear" | "saint-venant-kirchhoff" | "neo-hookean" (structure.model);
// std::invalid_argument otherwise.
MaterialModel material_model(const std::string& name);
const char* material_name(MaterialModel model);  // the inverse

struct Material {
  MaterialModel model = MaterialModel::linear;
  Lame lame;

  // Stored energy W(F) per unit reference area:
  //   SVK: λ/2 (tr E)² + μ E:E, E = ½(FᵀF − I);
  //   neo-Hookean: μ/2 (I₁ − 2 − 2 ln J) + λ/2 (ln J)², I₁ = tr FᵀF (SPEC §11);
  //   linear: λ/2 (tr ε)² + μ ε:ε, ε = sym(F − I).
  double energy(const Matrix2& F) const;
  // P = ∂W/∂F.
  Matrix2 stress(const Matrix2& F) const;
  // dP = ∂P/∂F [dF].
  Matrix2 stress_derivative(const Matrix2& F, const Matrix2& dF) const;
  // The tangent moduli A(2i + J, 2k + L) = ∂P_iJ/∂F_kL: stress_derivative along the four
  // unit directions (once per point: an assembly contracts them with each basis pair).
  Eigen::Matrix4d moduli(const Matrix2& F) const;
};

// F = I + ∇u on triangle t (u: 2nv, paper ordering); the same from its P1 geometry T
// and vertices `tri` (nv vertices).
Matrix2 deformation_gradient(const Mesh& mesh, int t, const Eigen::VectorXd& u);
Matrix2 deformation_gradient(const P1Triangle& T, const std::array<int, 3>& tri, const Eigen::VectorXd& u, int nv);
// ∫ W(F(u)) over Ω_S0.
double stored_energy(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u);
// f_int(u) (2nv).
Eigen::VectorXd internal_force(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u);
// K_T(u) (2nv × 2nv), symmetric (P derives from W). Its pattern is that of A_S for
// every u (the same triangles couple the same dofs), so one symbolic factorisation
// serves every Newton step.
SparseMatrix tangent_stiffness(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u);

}  // namespace fsi
