#include "fluid/convection.hpp"

#include "fem/quadrature.hpp"

namespace fsi {

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

namespace {

// The mini space's scalar basis s = (λ1, λ2, λ3, b), b = λ1λ2λ3; the vector basis is
// s_k e_c (mini_velocity_basis's index 3c + k, or 6 + c for the bubble). Each
// gradient is ∇s_l = Σ_a D_la ∇λ_a with D_la = δ_la for the hat functions and
// D_3a = ∂b/∂λ_a, so every integral the term needs is a contraction of one table
// on the reference triangle,
//     Q[k][m][l][a] = (1/|T|) ∫_T s_k s_m D_la      (degree 3+3+2 = 8: exact)
// with the element's data u_ma = c_m·∇λ_a (c_m: w's coefficients of s_m):
//     ∫ s_k (w·∇)s_l     = |T| Σ_ma Q[k][m][l][a] u_ma,
//     ∫ s_k s_l ∂_d w_c  = |T| Σ_ma Q[k][l][m][a] c_m,c ∂_d λ_a.
// Tabulated once, the assembly costs 5 products of 16×12 by 12 per triangle instead
// of the 25-point rule's per-point work: this term's share of a DFG 2D-1 run at 106k
// triangles fell from 19 % to 3 % (perf record; docs/performance.md, "Navier–Stokes"),
// and Newton repeats its assembly at every step.
struct ConvectionTables {
  Eigen::Matrix<double, 16, 12> advect;    // row 4k + l, column 3m + a: Q[k][m][l][a]
  Eigen::Matrix<double, 16, 12> gradient;  // row 4k + l, column 3m + a: Q[k][l][m][a]
};

ConvectionTables make_tables() {
  const TriangleRule rule = triangle_rule(8);
  double Q[4][4][4][3] = {};
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Eigen::Vector3d& l = rule.lambda[q];
    const double s[4] = {l[0], l[1], l[2], bubble_value(l)};
    double D[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {l[1] * l[2], l[0] * l[2], l[0] * l[1]}};
    for (int k = 0; k < 4; ++k)
      for (int m = 0; m < 4; ++m)
        for (int j = 0; j < 4; ++j)
          for (int a = 0; a < 3; ++a) Q[k][m][j][a] += rule.w[q] * s[k] * s[m] * D[j][a];
  }
  ConvectionTables tables;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int m = 0; m < 4; ++m)
        for (int a = 0; a < 3; ++a) {
          tables.advect(4 * k + j, 3 * m + a) = Q[k][m][j][a];
          tables.gradient(4 * k + j, 3 * m + a) = Q[k][j][m][a];
        }
  return tables;
}

const ConvectionTables& tables() {
  static const ConvectionTables t = make_tables();
  return t;
}

// w's coefficients per scalar basis function: row m = (c_m,1, c_m,2).
Eigen::Matrix<double, 4, 2> scalar_coefficients(const Eigen::Matrix<double, 8, 1>& c) {
  Eigen::Matrix<double, 4, 2> C;
  C.col(0) << c.segment<3>(0), c[6];
  C.col(1) << c.segment<3>(3), c[7];
  return C;
}

// A(k, l) = ρ ∫ s_k (w·∇)s_l on T.
Eigen::Matrix4d advection(double rho, const P1Triangle& T, const Eigen::Matrix<double, 4, 2>& C) {
  const Eigen::Matrix<double, 4, 3, Eigen::RowMajor> u = C * T.grad.transpose();  // u_ma = c_m·∇λ_a
  const Eigen::Matrix<double, 16, 1> a =
      (rho * T.area) * tables().advect.lazyProduct(Eigen::Map<const Eigen::Matrix<double, 12, 1>>(u.data()));  // 3m + a
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data());
}

// Index of the vector basis function s_k e_c in the 8 local velocity unknowns.
int vector_index(int k, int c) { return k < 3 ? 3 * c + k : 6 + c; }

}  // namespace

// J[(c,k),(d,l)] = ρ ∫ s_k [δ_cd (w·∇)s_l + s_l ∂_d w_c]: (w·∇)φ_j + (φ_j·∇)w tested with φ_i.
void NewtonConvection::add(int t, const P1Triangle& T, MiniLocal& e) const {
  const Eigen::Matrix<double, 4, 2> C = scalar_coefficients(velocity_coefficients(mesh_, w_, t));
  const Eigen::Matrix4d A = advection(rho_, T, C);
  Eigen::Matrix<double, 16, 4> S = Eigen::Matrix<double, 16, 4>::Zero();  // column 2c + d: ∫ s_k s_l ∂_d w_c
  if (!picard_) {
    Eigen::Matrix<double, 12, 4> V;  // row 3m + a, column 2c + d: c_m,c ∂_d λ_a
    for (int m = 0; m < 4; ++m)
      for (int a = 0; a < 3; ++a)
        for (int ci = 0; ci < 2; ++ci)
          for (int d = 0; d < 2; ++d) V(3 * m + a, 2 * ci + d) = C(m, ci) * T.grad(a, d);
    S.noalias() = (rho_ * T.area) * tables().gradient.lazyProduct(V);
  }
  Eigen::Matrix<double, 8, 8> J = Eigen::Matrix<double, 8, 8>::Zero();  // row: test φ_i; column: trial φ_j
  for (int ci = 0; ci < 2; ++ci)
    for (int d = 0; d < 2; ++d)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l)
          J(vector_index(k, ci), vector_index(l, d)) += (ci == d ? A(k, l) : 0.0) + S(4 * k + l, 2 * ci + d);
  e.M.topLeftCorner<6, 6>() += J.topLeftCorner<6, 6>();
  e.E_col.topRows<6>() += J.topRightCorner<6, 2>();
  e.E_row.leftCols<6>() += J.bottomLeftCorner<2, 6>();
  e.A_bb += J.bottomRightCorner<2, 2>();
  e.symmetric = false;
}

// ρ ∫ s_k (w·∇)w_c = Σ_l A(k, l) c_l,c: the advection matrix applied to w itself.
void NewtonConvection::add_load(int t, const P1Triangle& T, ElementLoad& load) const {
  if (picard_) return;  // Oseen's system has the Stokes load alone
  const Eigen::Matrix<double, 4, 2> C = scalar_coefficients(velocity_coefficients(mesh_, w_, t));
  const Eigen::Matrix<double, 4, 2> N = advection(rho_, T, C) * C;  // row k, column c
  for (int cc = 0; cc < 2; ++cc) {
    load.F_V.segment<3>(3 * cc) += N.col(cc).head<3>();
    load.F_b[cc] += N(3, cc);
  }
}

}  // namespace fsi
