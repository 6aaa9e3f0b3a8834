// The convective term's Newton pair on the mini space (fluid/convection.hpp): the load
// ρ∫(w·∇)w·φ is exact for a linear field (closed forms), and the Jacobian is its
// derivative (central differences are exact for a quadratic; J(w)w = 2 L(w)), bubbles
// included. The Newton iteration is the Navier–Stokes issue's; these are its parts.
#include "fluid/convection.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <sstream>

#include "fem/quadrature.hpp"
#include "fluid/penalised_stokes.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"

namespace fsi::convection_test {
namespace {

using Vector8d = Eigen::Matrix<double, 8, 1>;

struct OneTriangle {
  Mesh mesh;
  OneTriangle() {
    mesh.vertices = {Point(0.1, -0.2), Point(0.7, 0.05), Point(0.25, 0.6)};
    mesh.triangles = {{0, 1, 2}};
  }
  P1Triangle T() const { return P1Triangle(mesh, 0); }
  // A field with coefficients c in the basis order (v1 at 3 vertices, v2 at 3, bubble 2).
  FluidSolution field(const Vector8d& c) const {
    FluidSolution w;
    w.v1 = c.head<3>(), w.v2 = c.segment<3>(3);
    w.p = Eigen::Vector3d::Zero();
    w.bubble = Eigen::Matrix2Xd(2, 1);
    w.bubble << c[6], c[7];
    return w;
  }
};

Vector8d load_of(const NewtonConvection& term, const P1Triangle& T) {
  ElementLoad load;
  term.add_load(0, T, load);
  Vector8d L;
  L << load.F_V, load.F_b;
  return L;
}

Eigen::Matrix<double, 8, 8> jacobian_of(const NewtonConvection& term, const P1Triangle& T) {
  MiniLocal e;
  term.add(0, T, e);
  EXPECT_FALSE(e.symmetric);
  Eigen::Matrix<double, 8, 8> J;
  J.topLeftCorner<6, 6>() = e.M.topLeftCorner<6, 6>();
  J.topRightCorner<6, 2>() = e.E_col.topRows<6>();
  J.bottomLeftCorner<2, 6>() = e.E_row.leftCols<6>();
  J.bottomRightCorner<2, 2>() = e.A_bb;
  EXPECT_EQ(e.M.bottomRows<3>().norm(), 0.0);  // no pressure rows
  return J;
}

TEST(NewtonConvection, TheLoadOfALinearFieldIsItsClosedForm) {
  const OneTriangle one;
  const P1Triangle T = one.T();
  // w = (x, −y): (w·∇)w = (x, y); the bubble's coefficients 0.
  Vector8d c = Vector8d::Zero();
  for (int a = 0; a < 3; ++a) c[a] = one.mesh.vertices[a].x(), c[3 + a] = -one.mesh.vertices[a].y();
  const FluidSolution w = one.field(c);
  const double rho = 2.5;
  const Vector8d L = load_of(NewtonConvection(rho, one.mesh, w), T);
  // ∫ x λ_a = Σ_b x_b |T|(1 + δ_ab)/12, ∫ x b = Σ_b x_b |T|/180 (bubble::... closed forms).
  Vector8d exact = Vector8d::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      exact[a] += rho * one.mesh.vertices[b].x() * bubble::mass_p1(T.area, a, b);
      exact[3 + a] += rho * one.mesh.vertices[b].y() * bubble::mass_p1(T.area, a, b);
    }
  for (int b = 0; b < 3; ++b) {
    exact[6] += rho * one.mesh.vertices[b].x() * bubble::p1_times_bubble(T.area);
    exact[7] += rho * one.mesh.vertices[b].y() * bubble::p1_times_bubble(T.area);
  }
  EXPECT_LT((L - exact).cwiseAbs().maxCoeff(), 1e-14 * exact.cwiseAbs().maxCoeff()) << L.transpose();
}

TEST(NewtonConvection, TheJacobianIsTheLoadsDerivativeBubblesIncluded) {
  const OneTriangle one;
  const P1Triangle T = one.T();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  Vector8d c, d;
  for (int i = 0; i < 8; ++i) c[i] = U(rng), d[i] = U(rng);
  c.tail<2>() *= 20, d.tail<2>() *= 20;  // bubble coefficients of the P1 values' size at the centroid (b = 1/27)
  const double rho = 1.3, h = 0.5;  // L is quadratic in w: the central difference is exact for any h
  const FluidSolution w = one.field(c), w_plus = one.field(c + h * d), w_minus = one.field(c - h * d);
  const Eigen::Matrix<double, 8, 8> J = jacobian_of(NewtonConvection(rho, one.mesh, w), T);
  const Vector8d L = load_of(NewtonConvection(rho, one.mesh, w), T);
  const Vector8d dL = (load_of(NewtonConvection(rho, one.mesh, w_plus), T) -
                       load_of(NewtonConvection(rho, one.mesh, w_minus), T)) / (2 * h);
  const double scale = (J * d).cwiseAbs().maxCoeff();
  EXPECT_LT((J * d - dL).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((J * c - 2 * L).cwiseAbs().maxCoeff(), 1e-12 * L.cwiseAbs().maxCoeff());  // Euler: quadratic
  EXPECT_GT((J - J.transpose()).norm(), 1e-3 * J.norm());  // convection is not symmetric
}

// The tabulated contractions of NewtonConvection against the plain quadrature of
// their definitions on the 8 vector basis functions (mini_velocity_basis, the
// degree-8 rule): Newton's Jacobian, Picard's and the load, for a random field with
// bubbles, to round-off.
TEST(NewtonConvection, ItsTablesEqualTheQuadratureOfTheVectorBasis) {
  const OneTriangle one;
  const P1Triangle T = one.T();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  Vector8d c;
  for (int i = 0; i < 8; ++i) c[i] = U(rng);
  c.tail<2>() *= 20;
  const double rho = 0.7;
  const FluidSolution w = one.field(c);
  Eigen::Matrix<double, 8, 8> newton = Eigen::Matrix<double, 8, 8>::Zero(), picard = newton;
  Vector8d load = Vector8d::Zero();
  const TriangleRule rule = triangle_rule(8);
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const MiniVelocityBasis B = mini_velocity_basis(T, rule.lambda[q]);
    Eigen::Vector2d wq = Eigen::Vector2d::Zero();
    Eigen::Matrix2d grad_w = Eigen::Matrix2d::Zero();  // row c: ∇w_c
    for (int j = 0; j < 8; ++j) wq += c[j] * B.value[j], grad_w += c[j] * B.grad[j];
    const double dx = rho * rule.w[q] * T.area;
    for (int i = 0; i < 8; ++i) {
      load[i] += dx * B.value[i].dot(grad_w * wq);
      for (int j = 0; j < 8; ++j) {
        const double advect = B.value[i].dot(B.grad[j] * wq);  // φ_i·(w·∇)φ_j
        picard(i, j) += dx * advect;
        newton(i, j) += dx * (advect + B.value[i].dot(grad_w * B.value[j]));  // + φ_i·(φ_j·∇)w
      }
    }
  }
  NewtonConvection term(rho, one.mesh, w);
  EXPECT_LT((jacobian_of(term, T) - newton).cwiseAbs().maxCoeff(), 1e-13 * newton.cwiseAbs().maxCoeff());
  EXPECT_LT((load_of(term, T) - load).cwiseAbs().maxCoeff(), 1e-13 * load.cwiseAbs().maxCoeff());
  term.set_picard(true);
  EXPECT_LT((jacobian_of(term, T) - picard).cwiseAbs().maxCoeff(), 1e-13 * picard.cwiseAbs().maxCoeff());
  EXPECT_EQ(load_of(term, T).norm(), 0.0);  // Oseen's system: the Stokes load alone
}

// Newton's method for the steady Navier–Stokes equations of the paper's box (no
// structure, χ = 0) from the Stokes solution, each step K(w) w_new = F + ρ∫(w·∇)w·φ
// through PenalisedStokes with the term added once and its w updated in place: the
// increments fall quadratically (each ≤ C times the last squared) to round-off.
TEST(NewtonConvection, NewtonStepsThroughThePenalisedStokesSolverConvergeQuadratically) {
  const Case c = load_case("", {"fluid.h=0.05"});
  const Mesh mesh = make_fluid_mesh(c);
  const Point f_F = c.fluid->f;
  PenalisedStokes stokes(mesh, c.fluid->mu, c.coupling.eps, [f_F](const Point&) { return f_F; },
                         box_boundary_conditions(mesh, *c.fluid), "umfpack", FluidFactorization::whole);
  stokes.set_chi(Eigen::VectorXd::Zero(mesh.num_triangles()));
  FluidSolution w = stokes.solve();  // Stokes: the first iterate
  const double rho = 0.02;          // Re = ρ Vmax L1 / μ ≈ 19
  stokes.add_term(std::make_shared<NewtonConvection>(rho, mesh, w));
  std::vector<double> increments;
  for (int k = 0; k < 8 && (increments.empty() || increments.back() > 1e-10 * c.fluid->Vmax); ++k) {
    stokes.terms_changed();  // w changed
    const FluidSolution& next = stokes.solve();
    increments.push_back((next.v1 - w.v1).cwiseAbs().maxCoeff() + (next.v2 - w.v2).cwiseAbs().maxCoeff());
    w.v1 = next.v1, w.v2 = next.v2, w.p = next.p, w.bubble = next.bubble;
  }
  ASSERT_GE(increments.size(), 3u);
  EXPECT_LT(increments.back(), 1e-10 * c.fluid->Vmax) << "no convergence";
  EXPECT_LE(increments.size(), 6u) << "more steps than quadratic convergence takes";
  EXPECT_GT(increments.front(), 1e-3 * c.fluid->Vmax);  // inertia changes the flow
  std::ostringstream history;
  for (double d : increments) history << ' ' << d;
  // Quadratic: d_{k+1} ≤ C d_k² with C from the first pair, until round-off (~1e-12 m/s
  // here) is reached.
  const double C = increments[1] / (increments[0] * increments[0]), floor = 1e-10 * c.fluid->Vmax;
  for (std::size_t k = 1; k + 1 < increments.size(); ++k)
    EXPECT_LT(increments[k + 1], 10 * C * increments[k] * increments[k] + floor) << "step " << k + 1 << ":" << history.str();
}

}  // namespace
}  // namespace fsi::convection_test
