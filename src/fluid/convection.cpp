#include "fluid/convection.hpp"

#include "fem/quadrature.hpp"

namespace fsi {
namespace {

// w's 8 coefficients on triangle t in the basis order of mini_velocity_basis.
Eigen::Matrix<double, 8, 1> local_coefficients(const Mesh& mesh, const FluidSolution& w, int t) {
  Eigen::Matrix<double, 8, 1> c;
  const auto& tri = mesh.triangles[t];
  for (int a = 0; a < 3; ++a) c[a] = w.v1[tri[a]], c[3 + a] = w.v2[tri[a]];
  c[6] = w.bubble(0, t), c[7] = w.bubble(1, t);
  return c;
}

struct FieldAt {
  Eigen::Vector2d value = Eigen::Vector2d::Zero();
  Eigen::Matrix2d grad = Eigen::Matrix2d::Zero();
};

FieldAt field_at(const MiniVelocityBasis& B, const Eigen::Matrix<double, 8, 1>& c) {
  FieldAt f;
  for (int i = 0; i < 8; ++i) f.value += c[i] * B.value[i], f.grad += c[i] * B.grad[i];
  return f;
}

}  // namespace

MiniVelocityBasis mini_velocity_basis(const P1Triangle& T, const Eigen::Vector3d& l) {
  MiniVelocityBasis B;
  for (int i = 0; i < 8; ++i) B.value[i].setZero(), B.grad[i].setZero();
  const Eigen::Vector2d gb = bubble_gradient(T, l);
  for (int c = 0; c < 2; ++c) {
    for (int a = 0; a < 3; ++a) {
      B.value[3 * c + a][c] = l[a];
      B.grad[3 * c + a].row(c) = T.grad.row(a);
    }
    B.value[6 + c][c] = bubble_value(l);
    B.grad[6 + c].row(c) = gb.transpose();
  }
  return B;
}

void NewtonConvection::add(int t, const P1Triangle& T, MiniLocal& e) const {
  const Eigen::Matrix<double, 8, 1> c = local_coefficients(mesh_, w_, t);
  const TriangleRule rule = triangle_rule(8);
  Eigen::Matrix<double, 8, 8> J = Eigen::Matrix<double, 8, 8>::Zero();  // row: test φ_i; column: trial φ_j
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const MiniVelocityBasis B = mini_velocity_basis(T, rule.lambda[q]);
    const FieldAt w = field_at(B, c);
    const double dx = rho_ * rule.w[q] * T.area;
    for (int j = 0; j < 8; ++j) {
      Eigen::Vector2d Dj = B.grad[j] * w.value;  // (w·∇)φ_j
      if (!picard_) Dj += w.grad * B.value[j];    // + (φ_j·∇)w
      for (int i = 0; i < 8; ++i) J(i, j) += dx * B.value[i].dot(Dj);
    }
  }
  e.M.topLeftCorner<6, 6>() += J.topLeftCorner<6, 6>();
  e.E_col.topRows<6>() += J.topRightCorner<6, 2>();
  e.E_row.leftCols<6>() += J.bottomLeftCorner<2, 6>();
  e.A_bb += J.bottomRightCorner<2, 2>();
  e.symmetric = false;
}

void NewtonConvection::add_load(int t, const P1Triangle& T, ElementLoad& load) const {
  if (picard_) return;  // Oseen's system has the Stokes load alone
  const Eigen::Matrix<double, 8, 1> c = local_coefficients(mesh_, w_, t);
  const TriangleRule rule = triangle_rule(8);
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const MiniVelocityBasis B = mini_velocity_basis(T, rule.lambda[q]);
    const FieldAt w = field_at(B, c);
    const Eigen::Vector2d N = rho_ * rule.w[q] * T.area * (w.grad * w.value);  // ρ (w·∇)w dx
    for (int i = 0; i < 6; ++i) load.F_V[i] += B.value[i].dot(N);
    for (int d = 0; d < 2; ++d) load.F_b[d] += B.value[6 + d].dot(N);
  }
}

}  // namespace fsi
