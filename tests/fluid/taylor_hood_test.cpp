// The Taylor–Hood element (fluid/taylor_hood_system.hpp, taylor_hood_flow.hpp):
// manufactured solutions in space (Stokes and Navier–Stokes, both viscous forms:
// velocity O(h³) in L², O(h²) in H¹, pressure O(h²) in L², Brezzi & Fortin), the
// isoparametric hole's geometry (area O(h⁴) against O(h²) for straight edges), and
// BDF1/BDF2's orders in time on a flow the space holds exactly (only the time error left).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/iso_p2.hpp"
#include "fluid/taylor_hood_flow.hpp"
#include "mesh/generated_mesh.hpp"
#include "mesh/mesh_geometry.hpp"
#include "support/norms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::taylor_hood_test {
namespace {

constexpr double pi = std::numbers::pi;

// v = curl(sin πx sin πy / π): divergence-free, Δv = −2π² v.
Point v_exact(const Point& x) {
  return {std::sin(pi * x.x()) * std::cos(pi * x.y()), -std::cos(pi * x.x()) * std::sin(pi * x.y())};
}
Eigen::Matrix2d grad_v(const Point& x) {
  const double sx = std::sin(pi * x.x()), cx = std::cos(pi * x.x()), sy = std::sin(pi * x.y()),
               cy = std::cos(pi * x.y());
  return (Eigen::Matrix2d() << pi * cx * cy, -pi * sx * sy, pi * sx * sy, -pi * cx * cy).finished();
}
double p_exact(const Point& x) { return std::cos(pi * x.x()) * std::exp(x.y()); }
Point grad_p(const Point& x) {
  return {-pi * std::sin(pi * x.x()) * std::exp(x.y()), std::cos(pi * x.x()) * std::exp(x.y())};
}

struct Flow {
  TaylorHoodModel model;
  // f = −μΔv + ∇p + ρ(v·∇)v (either viscous form: div v = 0).
  Point f(const Point& x) const {
    return 2 * pi * pi * model.mu * v_exact(x) + grad_p(x) + model.rho * grad_v(x) * v_exact(x);
  }
  // σn on the right side (n = e_x) in the form's own flux.
  Point traction(const Point& x) const {
    const Eigen::Matrix2d g = grad_v(x);
    const Eigen::Matrix2d flux = model.form == ViscousForm::symmetric ? Eigen::Matrix2d(g + g.transpose()) : g;
    return model.mu * flux.col(0) - p_exact(x) * Point(1, 0);
  }
};

// The unit square in n × n, v prescribed on three sides and the traction on the right.
struct Square {
  Square(const Flow& flow, int n)
      : mesh(testing::structured_rectangle(1.0, 1.0, n, n)),
        space(mesh),
        geometry(space, {}, 5),
        system(geometry, flow.model, [&flow](const Point& x) { return flow.f(x); }, conditions(flow)),
        solver(system) {}
  FluidBoundaryConditions conditions(const Flow& flow) const {
    FluidBoundaryConditions bc;
    for (const char* side : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
    bc.g = v_exact;
    bc.tractions.emplace_back(mesh.label("right"), [flow](const Point& x) { return flow.traction(x); });
    return bc;
  }
  const Mesh mesh;
  const P2Space space;
  const IsoP2Geometry geometry;
  TaylorHoodSystem system;
  TaylorHoodFlow solver;
};

TaylorHoodErrors solve_square(const Flow& flow, int n) {
  Square square(flow, n);
  TaylorHoodSystem& system = square.system;
  TaylorHoodFlow& solver = square.solver;
  const Eigen::VectorXd& U = solver.solve();
  if (flow.model.rho == 0) {
    EXPECT_LE(solver.report().steps, 2);  // linear: one Newton step (and round-off)
  }
  return taylor_hood_errors(system, U, v_exact, grad_v, p_exact);
}

void expect_rates(const Flow& flow, const std::vector<int>& n = {4, 8, 16, 32}) {
  std::vector<TaylorHoodErrors> e;
  for (int k : n) e.push_back(solve_square(flow, k));
  for (std::size_t k = 1; k < n.size(); ++k) {
    const double h0 = 1.0 / n[k - 1], h1 = 1.0 / n[k];
    const double rv = testing::rate(e[k - 1].velocity_l2, e[k].velocity_l2, h0, h1);
    const double rg = testing::rate(e[k - 1].velocity_h1, e[k].velocity_h1, h0, h1);
    const double rp = testing::rate(e[k - 1].pressure_l2, e[k].pressure_l2, h0, h1);
    std::printf("n %d: |v|L2 %.3e (%.2f)  |v|H1 %.3e (%.2f)  |p|L2 %.3e (%.2f)\n", n[k], e[k].velocity_l2, rv,
                e[k].velocity_h1, rg, e[k].pressure_l2, rp);
    EXPECT_GE(rv, 2.8);
    EXPECT_GE(rg, 1.9);
    EXPECT_GE(rp, 1.9);
  }
}

TEST(TaylorHood, StokesConvergesAtTaylorHoodRatesInBothViscousForms) {
  expect_rates({{1.0, ViscousForm::symmetric, 0.0}});
  expect_rates({{1.0, ViscousForm::gradient, 0.0}});
}

TEST(TaylorHood, NavierStokesConvergesAtTaylorHoodRates) {
  Flow flow{{0.05, ViscousForm::gradient, 1.0}};  // Re of order 20 on the unit square
  expect_rates(flow);
  flow.model.form = ViscousForm::symmetric;
  expect_rates(flow, {4, 8, 16});  // the form's own terms: the gradient's rates above, to 16 × 16
}

// Newton's method converges quadratically: once near the solution, each relative
// residual is at most a constant times the square of the last (the constant measured
// about 10–200 here: at Re of order 100 on the unit square Newton from rest first
// takes a dozen damped steps).
TEST(TaylorHood, NewtonConvergesQuadratically) {
  const Flow flow{{0.01, ViscousForm::gradient, 1.0}};
  Square square(flow, 16);
  TaylorHoodFlow& solver = square.solver;
  solver.solve();
  const std::vector<double>& r = solver.report().residuals;
  ASSERT_GE(r.size(), 4u);
  EXPECT_LE(r.back(), 1e-10);
  EXPECT_LT(r[r.size() - 2], 1e-6);  // the last step from below 1e-6 to below 1e-10: not linear
  for (std::size_t k = 1; k < r.size(); ++k)
    if (r[k - 1] < 1e-3) {
      EXPECT_LE(r[k], 1e3 * r[k - 1] * r[k - 1] + 1e-13) << "step " << k;
    }
}

// The box with a circular hole: the isoparametric domain's area converges at O(h⁴),
// the straight-edged one's at O(h²).
TEST(TaylorHood, CurvedHoleMeetsTheCircleToFourthOrderInArea) {
  const double r = 0.15;
  const double exact = 1.0 * 1.0 - pi * r * r;
  std::vector<double> h, curved, straight;
  for (double size : {0.1, 0.05, 0.025}) {
    FluidGeometry g{1.0, 0.5, 0.5, 0.5, 0.0, r, size};
    const Mesh mesh = generate_fluid_mesh(g);
    const P2Space space(mesh);
    const int hole = mesh.label("Sigma_5");
    h.push_back(testing::mesh_size(mesh));
    curved.push_back(std::abs(IsoP2Geometry(space, {{hole, {0.5, 0.0}, r}}, 5).area() - exact));
    straight.push_back(std::abs(IsoP2Geometry(space, {}, 5).area() - exact));
    const IsoP2Geometry iso(space, {{hole, {0.5, 0.0}, r}}, 5);
    EXPECT_GT(iso.curved_triangles(), 0);
    for (int node : space.nodes_on(hole)) EXPECT_NEAR((iso.nodes()[node] - Point(0.5, 0.0)).norm(), r, 1e-12);
  }
  for (std::size_t k = 1; k < h.size(); ++k) {
    std::printf("h %.4f: area error curved %.3e, straight %.3e\n", h[k], curved[k], straight[k]);
    EXPECT_GE(testing::rate(curved[k - 1], curved[k], h[k - 1], h[k]), 3.5);
    EXPECT_LE(testing::rate(straight[k - 1], straight[k], h[k - 1], h[k]), 2.5);
    EXPECT_LT(curved[k], 0.01 * straight[k]);
  }
}

// v = (y², x²) cos t, p = (x + y) cos t lie in P2 × P1: the discrete solution is exact
// in space at every time, so its error at T is the scheme's alone. Navier–Stokes, the
// gradient form, a traction on the right.
struct March {
  double error;           // velocity in L² at T
  Eigen::VectorXd state;  // at T
  int factorizations, chord_steps;
};
March march(TimeScheme scheme, int steps, bool reuse_factors = true) {
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, 4, 4);
  const P2Space space(mesh);
  const IsoP2Geometry geometry(space, {}, 5);
  const TaylorHoodModel model{0.1, ViscousForm::gradient, 1.0};
  double t = 0;
  const auto v = [&](const Point& x) -> Point { return Point(x.y() * x.y(), x.x() * x.x()) * std::cos(t); };
  const auto f = [&](const Point& x) {
    const Point dvdt = -Point(x.y() * x.y(), x.x() * x.x()) * std::sin(t);
    const Point conv = Point(2 * x.x() * x.x() * x.y(), 2 * x.x() * x.y() * x.y()) * std::pow(std::cos(t), 2);
    return Point(dvdt - model.mu * Point(2, 2) * std::cos(t) + Point(1, 1) * std::cos(t) + conv);
  };
  const auto traction = [&](const Point& x) {  // μ ∂_x v − p e_x
    return Point(Point(0, 2 * model.mu * x.x()) * std::cos(t) - Point(x.x() + x.y(), 0) * std::cos(t));
  };
  FluidBoundaryConditions bc;
  for (const char* side : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
  bc.g = v;
  bc.tractions.emplace_back(mesh.label("right"), traction);
  TaylorHoodSystem system(geometry, model, f, bc);
  TaylorHoodOptions options;
  options.reuse_factors = reuse_factors;
  TaylorHoodFlow flow(system, options);
  Eigen::VectorXd U0 = Eigen::VectorXd::Zero(system.dofs());
  for (int i = 0; i < space.num_nodes(); ++i)
    for (int c = 0; c < 2; ++c) U0[system.velocity_dof(c, i)] = v(geometry.nodes()[i])[c];
  const double T = 1.0;
  flow.start(1.0, scheme, T / steps, U0);
  for (int k = 0; k < steps; ++k)
    flow.step([&](double time) {
      t = time;
      system.set_data(f, bc);
    });
  const auto v_now = [&](const Point& x) { return v(x); };
  const auto g_now = [&](const Point& x) {
    return Eigen::Matrix2d((Eigen::Matrix2d() << 0, 2 * x.y(), 2 * x.x(), 0).finished() * std::cos(t));
  };
  const auto p_now = [&](const Point& x) { return (x.x() + x.y()) * std::cos(t); };
  return {taylor_hood_errors(system, flow.state(), v_now, g_now, p_now).velocity_l2, flow.state(),
          flow.factorizations(), flow.chord_steps()};
}
double time_error(TimeScheme scheme, int steps) { return march(scheme, steps).error; }

TEST(TaylorHood, BdfStepsConvergeAtTheirOrdersInTime) {
  for (TimeScheme scheme : {TimeScheme::bdf1, TimeScheme::bdf2}) {
    const double order = scheme == TimeScheme::bdf1 ? 1 : 2;
    std::vector<double> e;
    for (int steps : {10, 20, 40}) e.push_back(time_error(scheme, steps));
    for (std::size_t k = 1; k < e.size(); ++k) {
      const double rate = std::log2(e[k - 1] / e[k]);
      std::printf("BDF%g: error %.3e, rate %.2f\n", order, e[k], rate);
      EXPECT_NEAR(rate, order, 0.15);
    }
  }
}

// The chord method (reused factors in time steps) reaches the same states as Newton's
// with a fresh Jacobian in every step, on a fraction of the factorisations.
TEST(TaylorHood, ReusedFactorsGiveNewtonsStatesWithFewerFactorisations) {
  const March chord = march(TimeScheme::bdf2, 40, true), newton = march(TimeScheme::bdf2, 40, false);
  std::printf("factorisations: %d reused (%d chord steps), %d fresh\n", chord.factorizations, chord.chord_steps,
              newton.factorizations);
  EXPECT_EQ(newton.chord_steps, 0);
  EXPECT_GT(chord.chord_steps, 40);
  EXPECT_LT(chord.factorizations, newton.factorizations / 4);
  EXPECT_LT((chord.state - newton.state).norm(), 1e-8 * newton.state.norm());
}

}  // namespace
}  // namespace fsi::taylor_hood_test
