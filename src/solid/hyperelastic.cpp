#include "solid/hyperelastic.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/errors.hpp"
#include "fem/integration.hpp"

namespace fsi {

MaterialModel material_model(const std::string& name) {
  if (name == "linear") return MaterialModel::linear;
  if (name == "saint-venant-kirchhoff") return MaterialModel::saint_venant_kirchhoff;
  if (name == "neo-hookean") return MaterialModel::neo_hookean;
  throw std::invalid_argument("unknown structure.model \"" + name + "\"");
}

const char* material_name(MaterialModel model) {
  switch (model) {
    case MaterialModel::linear: return "linear";
    case MaterialModel::saint_venant_kirchhoff: return "saint-venant-kirchhoff";
    case MaterialModel::neo_hookean: return "neo-hookean";
  }
  return "";
}

namespace {

// J = det F > 0, or a SolverFailure: the neo-Hookean energy is infinite at J → 0⁺ and
// undefined below; a Newton step that folds a triangle must be cut, not evaluated.
double positive_jacobian(const Matrix2& F) {
  const double J = F.determinant();
  if (!(J > 0)) throw SolverFailure("a triangle of the structure is inverted (det F = " + std::to_string(J) + ")");
  return J;
}

}  // namespace

double Material::energy(const Matrix2& F) const {
  const double l = lame.lambda, mu = lame.mu;
  switch (model) {
    case MaterialModel::linear: {
      const Matrix2 e = 0.5 * (F + F.transpose()) - Matrix2::Identity();
      return 0.5 * l * e.trace() * e.trace() + mu * (e.array() * e.array()).sum();
    }
    case MaterialModel::saint_venant_kirchhoff: {
      const Matrix2 E = 0.5 * (F.transpose() * F - Matrix2::Identity());
      return 0.5 * l * E.trace() * E.trace() + mu * (E.array() * E.array()).sum();
    }
    case MaterialModel::neo_hookean: {
      const double lnJ = std::log(positive_jacobian(F));
      return 0.5 * mu * ((F.array() * F.array()).sum() - 2 - 2 * lnJ) + 0.5 * l * lnJ * lnJ;
    }
  }
  return 0;
}

Matrix2 Material::stress(const Matrix2& F) const {
  const double l = lame.lambda, mu = lame.mu;
  const Matrix2 I = Matrix2::Identity();
  switch (model) {
    case MaterialModel::linear: {
      const Matrix2 e = 0.5 * (F + F.transpose()) - I;
      return l * e.trace() * I + 2 * mu * e;
    }
    case MaterialModel::saint_venant_kirchhoff: {  // P = F S, S = λ tr E I + 2μ E
      const Matrix2 E = 0.5 * (F.transpose() * F - I);
      return F * (l * E.trace() * I + 2 * mu * E);
    }
    case MaterialModel::neo_hookean: {  // P = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ
      const double lnJ = std::log(positive_jacobian(F));
      const Matrix2 Finv_T = F.inverse().transpose();
      return mu * (F - Finv_T) + l * lnJ * Finv_T;
    }
  }
  return Matrix2::Zero();
}

Matrix2 Material::stress_derivative(const Matrix2& F, const Matrix2& dF) const {
  const double l = lame.lambda, mu = lame.mu;
  const Matrix2 I = Matrix2::Identity();
  switch (model) {
    case MaterialModel::linear: {
      const Matrix2 de = 0.5 * (dF + dF.transpose());
      return l * de.trace() * I + 2 * mu * de;
    }
    case MaterialModel::saint_venant_kirchhoff: {  // dP = dF S + F dS, dE = sym(Fᵀ dF)
      const Matrix2 E = 0.5 * (F.transpose() * F - I);
      const Matrix2 dE = 0.5 * (dF.transpose() * F + F.transpose() * dF);
      return dF * (l * E.trace() * I + 2 * mu * E) + F * (l * dE.trace() * I + 2 * mu * dE);
    }
    case MaterialModel::neo_hookean: {
      // d(F⁻ᵀ) = −F⁻ᵀ dFᵀ F⁻ᵀ, d(ln J) = tr(F⁻¹ dF).
      const double lnJ = std::log(positive_jacobian(F));
      const Matrix2 Finv = F.inverse(), Finv_T = Finv.transpose();
      const Matrix2 dFinv_T = -Finv_T * dF.transpose() * Finv_T;
      return mu * (dF - dFinv_T) + l * (Finv * dF).trace() * Finv_T + l * lnJ * dFinv_T;
    }
  }
  return Matrix2::Zero();
}

Eigen::Matrix4d Material::moduli(const Matrix2& F) const {
  Eigen::Matrix4d A;
  for (int k = 0; k < 2; ++k)
    for (int L = 0; L < 2; ++L) {
      Matrix2 dF = Matrix2::Zero();
      dF(k, L) = 1;
      const Matrix2 dP = stress_derivative(F, dF);
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) A(2 * i + J, 2 * k + L) = dP(i, J);
    }
  return A;
}

Matrix2 deformation_gradient(const P1Triangle& T, const std::array<int, 3>& tri, const Eigen::VectorXd& u, int nv) {
  Matrix2 F = Matrix2::Identity();
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 2; ++c) F.row(c) += u[dof(tri[a], c, nv)] * T.grad.row(a);
  return F;
}

Matrix2 deformation_gradient(const Mesh& mesh, int t, const Eigen::VectorXd& u) {
  return deformation_gradient(P1Triangle(mesh, t), mesh.triangles[t], u, mesh.num_vertices());
}

double stored_energy(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u) {
  double W = 0;
  for_each_triangle(mesh, [&](int t, const P1Triangle& T) { W += T.area * m.energy(deformation_gradient(mesh, t, u)); });
  return W;
}

// The basis function φ_a e_c has ∇(φ_a e_c) = e_c ⊗ ∇λ_a: row c holds ∇λ_a.
namespace {
Matrix2 basis_gradient(const P1Triangle& T, int a, int c) {
  Matrix2 G = Matrix2::Zero();
  G.row(c) = T.grad.row(a);
  return G;
}
}  // namespace

Eigen::VectorXd internal_force(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * nv);
  for_each_triangle(mesh, [&](int t, const P1Triangle& T) {
    const Matrix2 P = m.stress(deformation_gradient(mesh, t, u));
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) f[dof(mesh.triangles[t][a], c, nv)] += T.area * P.row(c).dot(T.grad.row(a));
  });
  return f;
}

SparseMatrix tangent_stiffness(const Mesh& mesh, const Material& m, const Eigen::VectorXd& u) {
  const int nv = mesh.num_vertices();
  return assemble_on_triangles(mesh, 2 * nv, 2 * nv, 36, [&](int t, const P1Triangle& T, const auto& add) {
    const Matrix2 F = deformation_gradient(mesh, t, u);
    const auto& tri = mesh.triangles[t];
    for (int b = 0; b < 3; ++b)
      for (int d = 0; d < 2; ++d) {  // column (b, d): dP along ∇(φ_b e_d)
        const Matrix2 dP = m.stress_derivative(F, basis_gradient(T, b, d));
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 2; ++c) add(dof(tri[a], c, nv), dof(tri[b], d, nv), T.area * dP.row(c).dot(T.grad.row(a)));
      }
  });
}

}  // namespace fsi
