// The fluid's time derivative (SPEC §12, fluid/time_derivative.hpp) and its stepper
// (fluid/fluid_time_stepper.hpp): the term against the quadrature of its definition,
// BDF1's and BDF2's exactness and orders in time on a flow whose every time lies in
// the mini space (so that the error is the scheme's alone), Stokes and Navier–Stokes,
// and the unsteady Navier–Stokes flow's approach to the steady solution.
#include "fluid/time_derivative.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "fem/quadrature.hpp"
#include "fluid/convection.hpp"
#include "fluid/fluid_time_stepper.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fluid/stokes_residual.hpp"
#include "support/norms.hpp"
#include "support/stokes_norms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::time_derivative_test {
namespace {

using Vector8d = Eigen::Matrix<double, 8, 1>;

FluidSolution one_triangle_state(const Vector8d& c) {
  FluidSolution s;
  s.v1 = c.head<3>(), s.v2 = c.segment<3>(3), s.p = Eigen::Vector3d::Zero();
  s.bubble = Eigen::Matrix2Xd(2, 1);
  s.bubble << c[6], c[7];
  return s;
}

TEST(FluidTimeDerivative, BdfWeightsAndBdf2sFirstStep) {
  const BdfWeights first = bdf_weights(TimeScheme::bdf2, 0), later = bdf_weights(TimeScheme::bdf2, 3);
  EXPECT_EQ(first.alpha, 1.0);
  EXPECT_EQ(first.beta2, 0.0);
  EXPECT_EQ(later.alpha, 1.5);
  EXPECT_EQ(later.beta1, 2.0);
  EXPECT_EQ(later.beta2, -0.5);
  EXPECT_EQ(later.alpha, later.beta1 + later.beta2);  // constants are steady
  EXPECT_EQ(bdf_weights(TimeScheme::bdf1, 5).alpha, 1.0);
}

// Its matrix ρα/Δt ∫ φ_j·φ_i and its load ρ/Δt ∫ (β₁ v^n + β₂ v^{n−1})·φ_i against the
// degree-8 quadrature of the 8 vector basis functions (bubbles included).
TEST(FluidTimeDerivative, IsTheMassOfTheMiniSpace) {
  Mesh mesh;
  mesh.vertices = {Point(0.1, -0.2), Point(0.7, 0.05), Point(0.25, 0.6)};
  mesh.triangles = {{0, 1, 2}};
  const P1Triangle T(mesh, 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  Vector8d cn, cm;
  for (int i = 0; i < 8; ++i) cn[i] = U(rng), cm[i] = U(rng);
  const FluidSolution vn = one_triangle_state(cn), vm = one_triangle_state(cm);
  const double rho = 1.7, dt = 0.03;
  const BdfWeights w = bdf_weights(TimeScheme::bdf2, 1);
  FluidTimeDerivative term(rho, mesh);
  term.set_step(dt, w, vn, &vm);
  MiniLocal e;
  term.add(0, T, e);
  ElementLoad load;
  term.add_load(0, T, load);

  Eigen::Matrix<double, 8, 8> mass = Eigen::Matrix<double, 8, 8>::Zero();
  const TriangleRule rule = triangle_rule(8);
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const MiniVelocityBasis B = mini_velocity_basis(T, rule.lambda[q]);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) mass(i, j) += rule.w[q] * T.area * B.value[i].dot(B.value[j]);
  }
  Eigen::Matrix<double, 8, 8> M;
  M.topLeftCorner<6, 6>() = e.M.topLeftCorner<6, 6>();
  M.topRightCorner<6, 2>() = e.E_col.topRows<6>();
  M.bottomLeftCorner<2, 6>() = e.E_row.leftCols<6>();
  M.bottomRightCorner<2, 2>() = e.A_bb;
  const double coefficient = rho * w.alpha / dt;
  EXPECT_LT((M - coefficient * mass).cwiseAbs().maxCoeff(), 1e-13 * coefficient * mass.cwiseAbs().maxCoeff());
  EXPECT_TRUE(e.symmetric);
  Vector8d L;
  L << load.F_V, load.F_b;
  const Vector8d expected = rho / dt * mass * (w.beta1 * cn + w.beta2 * cm);
  EXPECT_LT((L - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
}

// v = φ(t) (y, 0), p = 0 on the unit square: ρ∂_t v − μΔv + ∇p = (ρ φ'(t) y, 0) and
// (v·∇)v = 0, so it solves Stokes and Navier–Stokes alike; the velocity prescribed
// on the left, bottom and top (changing in time), the right side traction-free in the
// gradient form (∂_x v = 0 there). v(t) lies in the mini space at every t, so the
// semi-discrete solution is exact and the error at t is the time scheme's alone.
struct ShearInTime {
  std::function<double(double)> phi, dphi;
  double rho = 1.3, mu = 0.1;
  double now = 0;  // the time the data below are evaluated at
  Point v(const Point& x) const { return {phi(now) * x.y(), 0.0}; }
  Eigen::Matrix2d grad(const Point&) const { return (Eigen::Matrix2d() << 0, phi(now), 0, 0).finished(); }
};

FluidBoundaryConditions shear_conditions(const Mesh& mesh, const ShearInTime& flow) {
  FluidBoundaryConditions bc;
  for (const char* side : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
  bc.g = [&flow](const Point& x) { return flow.v(x); };
  return bc;
}

// The velocity's L² error at t = 1 after steps of Δt = 1/steps from rest.
double shear_error(ShearInTime& flow, TimeScheme scheme, int steps, bool navier_stokes, int n = 4) {
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, n, n);
  flow.now = 0;
  const auto force = [&flow](const Point& x) { return Point(flow.rho * flow.dphi(flow.now) * x.y(), 0.0); };
  PenalisedStokes fluid(mesh, flow.mu, 1.0, force, shear_conditions(mesh, flow),
                        navier_stokes ? kNavierStokesSolver : kDefaultSparseSolver, FluidFactorization::whole);
  fluid.set_viscous_form(ViscousForm::gradient);
  if (navier_stokes) fluid.set_navier_stokes({flow.rho, 1e-12, 30});
  FluidTimeStepper stepper(fluid, flow.rho, scheme, 1.0 / steps, fluid_at_rest(mesh));
  for (int k = 0; k < steps; ++k)
    stepper.step([&](double t) {
      flow.now = t;
      fluid.set_body_force(force);
      fluid.set_boundary_data(shear_conditions(mesh, flow));
    });
  EXPECT_NEAR(stepper.time(), 1.0, 1e-12);
  flow.now = stepper.time();
  return testing::mini_errors(mesh, stepper.state(), [&](const Point& x) { return flow.v(x); },
                              [&](const Point& x) { return flow.grad(x); }, [](const Point&) { return 0.0; })
      .v_l2;
}

// φ(t) = t: BDF1's difference quotient is exact for it, and BDF2's (started by BDF1)
// too: both reproduce the flow to round-off.
TEST(FluidTimeStepper, BothSchemesAreExactForAFlowLinearInTime) {
  for (bool navier_stokes : {false, true})
    for (TimeScheme scheme : {TimeScheme::bdf1, TimeScheme::bdf2}) {
      ShearInTime flow{[](double t) { return t; }, [](double) { return 1.0; }};
      EXPECT_LT(shear_error(flow, scheme, 5, navier_stokes), 1e-12)
          << (navier_stokes ? "Navier–Stokes" : "Stokes") << ", BDF" << (scheme == TimeScheme::bdf1 ? 1 : 2);
    }
}

// φ(t) = sin 3t: the error at t = 1 falls like Δt for BDF1 and Δt² for BDF2 (whose
// first step, BDF1's, makes its coarsest pair pre-asymptotic: rates 1.73, 1.89, 1.95
// from Δt = 1/10; here from 1/20).
TEST(FluidTimeStepper, Bdf1IsOfOrderOneAndBdf2OfOrderTwo) {
  for (bool navier_stokes : {false, true})
    for (TimeScheme scheme : {TimeScheme::bdf1, TimeScheme::bdf2}) {
      const int order = scheme == TimeScheme::bdf1 ? 1 : 2;
      const std::vector<int> steps{20, 40, 80, 160};
      std::vector<double> e;
      for (int n : steps) {
        ShearInTime flow{[](double t) { return std::sin(3 * t); }, [](double t) { return 3 * std::cos(3 * t); }};
        e.push_back(shear_error(flow, scheme, n, navier_stokes));
      }
      std::printf("%s BDF%d: L2 errors at t = 1 for dt = 1/20 ... 1/160:", navier_stokes ? "Navier-Stokes" : "Stokes",
                  order);
      for (double x : e) std::printf(" %.3e", x);
      std::printf("; rates");
      for (std::size_t k = 0; k + 1 < e.size(); ++k) std::printf(" %.2f", std::log2(e[k] / e[k + 1]));
      std::printf("\n");
      for (std::size_t k = 0; k + 1 < e.size(); ++k) {
        const double r = std::log2(e[k] / e[k + 1]);
        const bool finest = k + 2 == e.size();
        EXPECT_GT(r, order - (finest ? 0.07 : 0.15)) << "dt 1/" << steps[k] << " -> 1/" << steps[k + 1];
        EXPECT_LT(r, order + 0.2);
      }
    }
}

// The residual force with the step's ρ∂v/∂t (MomentumModel::inertia): the shear flow
// φ = t drags the bottom wall with μφ(t) per unit length (the gradient form's
// traction), exactly, since every step reproduces the flow; without the inertia the
// residual keeps ∫ρφ'y φ_i of the body force, about ρh²/6 = 13 % of it on 4 × 4 squares.
TEST(FluidTimeStepper, TheResidualForceIncludesTheTimeDerivative) {
  for (TimeScheme scheme : {TimeScheme::bdf1, TimeScheme::bdf2}) {
    ShearInTime flow{[](double t) { return t; }, [](double) { return 1.0; }};
    const Mesh mesh = testing::structured_rectangle(1.0, 1.0, 4, 4);
    const auto force = [&flow](const Point& x) { return Point(flow.rho * flow.dphi(flow.now) * x.y(), 0.0); };
    PenalisedStokes fluid(mesh, flow.mu, 1.0, force, shear_conditions(mesh, flow));
    fluid.set_viscous_form(ViscousForm::gradient);
    FluidTimeStepper stepper(fluid, flow.rho, scheme, 0.25, fluid_at_rest(mesh));
    EXPECT_EQ(stepper.last_step_inertia(), nullptr);
    for (int k = 0; k < 3; ++k)
      stepper.step([&](double t) {
        flow.now = t;
        fluid.set_body_force(force);
        fluid.set_boundary_data(shear_conditions(mesh, flow));
      });
    const int bottom = mesh.label("bottom");
    const MomentumModel with{flow.mu, ViscousForm::gradient, 0.0, stepper.last_step_inertia()};
    const Point F = hole_force(mesh, with, force, stepper.state(), bottom, {});
    EXPECT_NEAR(F.x(), flow.mu * 0.75, 1e-12);
    EXPECT_NEAR(F.y(), 0.0, 1e-12);
    const Point without = hole_force(mesh, MomentumModel{flow.mu, ViscousForm::gradient}, force, stepper.state(), bottom, {});
    EXPECT_GT(std::abs(without.x() - flow.mu * 0.75), 0.05 * flow.mu * 0.75);
  }
}

// The Navier–Stokes flow of tests/fluid/navier_stokes_test.cpp's manufactured
// solution (Re = 20) started from rest with steady data: BDF2 with Newton in each step
// approaches the discrete steady solution, the difference decaying like e^{−νλ₁t}
// (ν = μ/ρ = 0.05, λ₁ ≈ 2π²: about 1/s) until the solvers' tolerance.
TEST(FluidTimeStepper, AnUnsteadyNavierStokesFlowReachesTheSteadySolution) {
  constexpr double pi = std::numbers::pi, mu = 0.05, rho = 1.0;
  const auto v_exact = [](const Point& x) {
    return Point(std::sin(pi * x.x()) * std::cos(pi * x.y()), -std::cos(pi * x.x()) * std::sin(pi * x.y()));
  };
  const auto force = [&](const Point& x) {
    const Point v = v_exact(x);
    const Point convection(pi * std::sin(pi * x.x()) * std::cos(pi * x.x()), pi * std::sin(pi * x.y()) * std::cos(pi * x.y()));
    return Point(2 * pi * pi * mu * v + rho * convection);  // p = 0
  };
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, 10, 10);
  FluidBoundaryConditions bc;
  for (const char* side : {"left", "right", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
  bc.g = v_exact;
  PenalisedStokes steady(mesh, mu, 1.0, force, bc, kNavierStokesSolver, FluidFactorization::whole);
  steady.set_viscous_form(ViscousForm::gradient);
  steady.set_navier_stokes({rho, 1e-12, 30});
  const FluidSolution target = steady.solve();

  PenalisedStokes fluid(mesh, mu, 1.0, force, bc, kNavierStokesSolver, FluidFactorization::whole);
  fluid.set_viscous_form(ViscousForm::gradient);
  fluid.set_navier_stokes({rho, 1e-12, 30});
  FluidSolution rest = fluid_at_rest(mesh);
  FluidTimeStepper stepper(fluid, rho, TimeScheme::bdf2, 0.5, rest);
  std::vector<double> gap;
  for (int k = 0; k < 60; ++k) {
    const FluidSolution& v = stepper.step();
    gap.push_back(std::max((v.v1 - target.v1).cwiseAbs().maxCoeff(), (v.v2 - target.v2).cwiseAbs().maxCoeff()));
  }
  std::printf("max |v - v_steady| at t = 5, 10, 20, 30: %.2e %.2e %.2e %.2e\n", gap[9], gap[19], gap[39], gap[59]);
  EXPECT_GT(gap[0], 1e-2);  // inertia: the first step is far from steady
  EXPECT_LT(gap[39], 1e-6);
  EXPECT_LT(gap[59], 1e-9);
  EXPECT_LT(gap[59], 1e-3 * gap[19]);  // it decays, not merely stays small
}

// time.convection = "semi-implicit": one Oseen solve a step about 2vⁿ − vⁿ⁻¹. On the
// same Navier–Stokes flow from rest, (a) it keeps the steady solution's fixed point
// (at a steady state the extrapolation is the state: Oseen's equation is the steady
// one), and (b) it differs from the implicit steps by the extrapolation's O(Δt²).
struct ManufacturedNs {
  static constexpr double pi = std::numbers::pi, mu = 0.05, rho = 1.0;
  Mesh mesh = testing::structured_rectangle(1.0, 1.0, 10, 10);
  static Point v_exact(const Point& x) {
    return Point(std::sin(pi * x.x()) * std::cos(pi * x.y()), -std::cos(pi * x.x()) * std::sin(pi * x.y()));
  }
  static Point force(const Point& x) {
    const Point convection(pi * std::sin(pi * x.x()) * std::cos(pi * x.x()), pi * std::sin(pi * x.y()) * std::cos(pi * x.y()));
    return Point(2 * pi * pi * mu * v_exact(x) + rho * convection);
  }
  std::unique_ptr<PenalisedStokes> fluid(bool semi_implicit) const {
    FluidBoundaryConditions bc;
    for (const char* side : {"left", "right", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
    bc.g = v_exact;
    auto f = std::make_unique<PenalisedStokes>(mesh, mu, 1.0, force, bc, kNavierStokesSolver, FluidFactorization::whole);
    f->set_viscous_form(ViscousForm::gradient);
    f->set_navier_stokes({rho, 1e-12, 30, semi_implicit});
    return f;
  }
  // The state after `steps` BDF2 steps of dt from rest.
  FluidSolution march(bool semi_implicit, double dt, int steps) const {
    auto f = fluid(semi_implicit);
    FluidTimeStepper stepper(*f, rho, TimeScheme::bdf2, dt, fluid_at_rest(mesh));
    for (int k = 0; k < steps; ++k) stepper.step();
    if (semi_implicit) {
      EXPECT_EQ(f->newton()->total_steps, 0);  // one Oseen solve a step, no Newton step
    }
    return stepper.state();
  }
};

double max_difference(const FluidSolution& a, const FluidSolution& b) {
  return std::max((a.v1 - b.v1).cwiseAbs().maxCoeff(), (a.v2 - b.v2).cwiseAbs().maxCoeff());
}

TEST(FluidTimeStepper, SemiImplicitConvectionKeepsTheSteadyFixedPoint) {
  const ManufacturedNs ns;
  const FluidSolution target = ns.fluid(false)->solve();
  const FluidSolution v = ns.march(true, 0.5, 60);
  EXPECT_LT(max_difference(v, target), 1e-9);
}

TEST(FluidTimeStepper, SemiImplicitConvectionDiffersFromImplicitByDtSquared) {
  const ManufacturedNs ns;
  std::vector<double> d;
  for (int steps : {10, 20, 40, 80})
    d.push_back(max_difference(ns.march(true, 1.0 / steps, steps), ns.march(false, 1.0 / steps, steps)));
  std::printf("semi-implicit - implicit at t = 1, dt = 1/10 ... 1/80: %.2e %.2e %.2e %.2e\n", d[0], d[1], d[2], d[3]);
  for (std::size_t k = 0; k + 1 < d.size(); ++k) {
    EXPECT_GT(std::log2(d[k] / d[k + 1]), 1.8) << k;
    EXPECT_LT(std::log2(d[k] / d[k + 1]), 2.4) << k;
  }
}

TEST(FluidTimeStepper, RefusesANonPositiveStepAndNewLabels) {
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, 2, 2);
  FluidBoundaryConditions bc;
  bc.dirichlet_labels = {mesh.label("left"), mesh.label("bottom")};
  PenalisedStokes fluid(mesh, 1.0, 1.0, [](const Point&) { return Point(0, 0); }, bc);
  EXPECT_THROW(FluidTimeStepper(fluid, 1.0, TimeScheme::bdf1, 0.0, fluid_at_rest(mesh)), std::invalid_argument);
  FluidBoundaryConditions other = bc;
  other.dirichlet_labels.push_back(mesh.label("top"));
  EXPECT_THROW(fluid.set_boundary_data(other), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::time_derivative_test
