// Steady Navier–Stokes on the mini element (SPEC §10, fluid/newton_solve.hpp):
// manufactured solutions at a Reynolds number where convection dominates the error,
// exactness where the exact solution lies in the discrete space, the Stokes limit
// ρ → 0, Newton's quadratic convergence, Picard's rescue and Newton's refusal.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <sstream>

#include "common/errors.hpp"
#include "fluid/penalised_stokes.hpp"
#include "support/norms.hpp"
#include "support/stokes_norms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::navier_stokes_test {
namespace {

constexpr double pi = std::numbers::pi;

// v = (sin πx cos πy, −cos πx sin πy) (divergence-free, |v| ≤ 1), p = cos πx eʸ.
Point v_exact(const Point& x) {
  return {std::sin(pi * x.x()) * std::cos(pi * x.y()), -std::cos(pi * x.x()) * std::sin(pi * x.y())};
}
Eigen::Matrix2d grad_v(const Point& x) {  // row i: ∇v_i
  const double sx = std::sin(pi * x.x()), cx = std::cos(pi * x.x()), sy = std::sin(pi * x.y()),
               cy = std::cos(pi * x.y());
  Eigen::Matrix2d g;
  g << pi * cx * cy, -pi * sx * sy, pi * sx * sy, -pi * cx * cy;
  return g;
}
double p_exact(const Point& x) { return std::cos(pi * x.x()) * std::exp(x.y()); }
Point grad_p(const Point& x) {
  return {-pi * std::sin(pi * x.x()) * std::exp(x.y()), std::cos(pi * x.x()) * std::exp(x.y())};
}

struct Flow {
  double mu, rho;
  // −μΔv + ρ(v·∇)v + ∇p, with Δv = −2π² v.
  Point f(const Point& x) const { return 2 * pi * pi * mu * v_exact(x) + rho * grad_v(x) * v_exact(x) + grad_p(x); }
  // The gradient form's traction μ ∇v n − p n on the outlet y = 0 (n = −e_y).
  Point h(const Point& x) const {
    const Point n(0, -1);
    return mu * grad_v(x) * n - p_exact(x) * n;
  }
};

FluidBoundaryConditions mms_conditions(const Mesh& mesh, const Flow& flow) {
  FluidBoundaryConditions bc;
  for (const char* side : {"left", "right", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
  bc.g = v_exact;
  bc.tractions.emplace_back(mesh.label("bottom"), [flow](const Point& x) { return flow.h(x); });
  return bc;
}

testing::StokesErrors solve_mms(int n, const Flow& flow, bool navier_stokes) {
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, n, n);
  PenalisedStokes fluid(mesh, flow.mu, 1.0, [flow](const Point& x) { return flow.f(x); }, mms_conditions(mesh, flow),
                        kNavierStokesSolver, FluidFactorization::whole);
  fluid.set_viscous_form(ViscousForm::gradient);
  if (navier_stokes) fluid.set_navier_stokes({flow.rho, 1e-10, 30});
  const FluidSolution& s = fluid.solve();
  if (navier_stokes) {
    std::printf("n %3d: Newton %d (%d damped), Picard %d:", n, fluid.newton()->steps, fluid.newton()->damped,
                fluid.newton()->picard_steps);
    for (double r : fluid.newton()->residuals) std::printf(" %.1e", r);
    std::printf("\n");
  }
  return testing::mini_errors(mesh, s, v_exact, grad_v, p_exact);
}

// μ = 0.05, ρ = 1, |v| ≤ 1 on the unit square: Re = ρ U L / μ = 20, the convection
// ρ(v·∇)v (size π/2) 1.6 times the viscous term μΔv (2π²μ). Convection dominates the
// error: the same meshes with the convection left out of the discrete problem (f
// still Navier–Stokes's) miss the solution by O(1), and with it the errors fall at
// the mini element's rates: velocity L² 2, H¹ 1, pressure L² ≥ 1.5. (At Re = 100
// this forced flow has other discrete steady solutions, which the damped Newton
// iteration from rest finds on some meshes: a manufactured solution needs a unique one.)
TEST(NavierStokesMms, MiniElementRatesAtReynolds20) {
  const Flow flow{0.05, 1.0};
  std::vector<testing::StokesErrors> e;
  std::vector<double> h;
  for (int n : {8, 16, 32, 64}) {  // (128 takes two minutes in the sanitizers' build)
    h.push_back(1.0 / n);
    e.push_back(solve_mms(n, flow, true));
    std::printf("n %3d  |v|L2 %.3e  |v|H1 %.3e  |p|L2 %.3e\n", n, e.back().v_l2, e.back().v_h1, e.back().p_l2);
  }
  for (std::size_t k = 1; k + 1 < h.size(); ++k) {  // the first pair is pre-asymptotic
    const double rv = testing::rate(e[k].v_l2, e[k + 1].v_l2, h[k], h[k + 1]);
    const double rg = testing::rate(e[k].v_h1, e[k + 1].v_h1, h[k], h[k + 1]);
    const double rp = testing::rate(e[k].p_l2, e[k + 1].p_l2, h[k], h[k + 1]);
    std::printf("rates %zu: velocity L2 %.2f, H1 %.2f, pressure L2 %.2f\n", k, rv, rg, rp);
    EXPECT_GE(rv, 1.8);
    EXPECT_GE(rg, 0.9);
    EXPECT_GE(rp, 1.5);
  }
  const testing::StokesErrors without = solve_mms(64, flow, false);
  EXPECT_GT(without.v_l2, 20 * e[3].v_l2) << "the convection must dominate the error";
}

// Couette flow v = (y, 0), p = 0 lies in the discrete space and solves Navier–Stokes
// ((v·∇)v = 0) with a traction-free outlet x = 1 in the gradient form: exact to
// round-off at any ρ, the bubbles zero.
TEST(NavierStokes, CouetteFlowIsExactAtAnyDensity) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 12, 6);
  FluidBoundaryConditions bc;
  for (const char* side : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
  bc.g = [](const Point& x) { return Point(x.y(), 0); };
  for (double rho : {1.0, 1e3}) {
    PenalisedStokes fluid(mesh, 1e-3, 1.0, [](const Point&) { return Point(0, 0); }, bc, kNavierStokesSolver,
                          FluidFactorization::whole);
    fluid.set_viscous_form(ViscousForm::gradient);
    fluid.set_navier_stokes({rho, 1e-10, 30});
    const FluidSolution& s = fluid.solve();
    double err = s.bubble.cwiseAbs().maxCoeff() + s.v2.cwiseAbs().maxCoeff() + s.p.cwiseAbs().maxCoeff();
    for (int v = 0; v < mesh.num_vertices(); ++v) err = std::max(err, std::abs(s.v1[v] - mesh.vertices[v].y()));
    EXPECT_LT(err, 1e-12) << "rho " << rho;
  }
}

// Poiseuille flow v = (4U y(1 − y), 0), p = 8μU(4 − x) in (0,4)×(0,1) solves
// Navier–Stokes too ((v·∇)v = 0), and the gradient form's do-nothing outflow at x = 4
// holds for it exactly: with inertia (Re = ρU/μ = 100) the velocity converges at rate
// 2 as with Stokes, to errors within 10 % of Stokes's.
TEST(NavierStokes, PoiseuilleFlowIsTheSolutionWithInertiaToo) {
  const double U = 1, mu = 0.01;
  auto v = [U](const Point& x) { return Point(4 * U * x.y() * (1 - x.y()), 0); };
  auto grad = [U](const Point& x) {
    Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
    g(0, 1) = 4 * U * (1 - 2 * x.y());
    return g;
  };
  auto p = [U, mu](const Point& x) { return 8 * mu * U * (4 - x.x()); };
  std::vector<double> ns_error, stokes_error;
  for (int n : {8, 16, 32}) {
    const Mesh mesh = testing::structured_rectangle(4.0, 1.0, 4 * n, n);
    FluidBoundaryConditions bc;
    for (const char* side : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
    bc.g = v;
    for (bool inertia : {true, false}) {
      PenalisedStokes fluid(mesh, mu, 1.0, [](const Point&) { return Point(0, 0); }, bc, kNavierStokesSolver,
                            FluidFactorization::whole);
      fluid.set_viscous_form(ViscousForm::gradient);
      if (inertia) fluid.set_navier_stokes({1.0, 1e-10, 30});
      const double e = testing::mini_errors(mesh, fluid.solve(), v, grad, p).v_l2;
      (inertia ? ns_error : stokes_error).push_back(e);
    }
    std::printf("n %2d  |v|L2 Navier-Stokes %.3e, Stokes %.3e\n", n, ns_error.back(), stokes_error.back());
  }
  for (std::size_t k = 0; k < ns_error.size(); ++k) EXPECT_LT(ns_error[k], 1.1 * stokes_error[k]);
  EXPECT_GE(std::log2(ns_error[1] / ns_error[2]), 1.8);
}

struct PaperBox {
  Mesh mesh = testing::structured_rectangle(0.41, 1.0, 12, 30);
  FluidBoundaryConditions bc;
  PaperBox() {
    for (const char* side : {"left", "right", "top"}) bc.dirichlet_labels.push_back(mesh.label(side));
    bc.dirichlet_values.emplace_back(mesh.label("top"),
                                     [](const Point& x) { return Point(0, 8.0 * 4 * x.x() * (x.x() - 0.41) / (0.41 * 0.41)); });
  }
  std::unique_ptr<PenalisedStokes> fluid(double mu, const std::string& solver) const {
    auto s = std::make_unique<PenalisedStokes>(mesh, mu, 1e-5, [](const Point&) { return Point(0, -981); }, bc, solver,
                                               FluidFactorization::whole);
    Eigen::VectorXd chi = Eigen::VectorXd::Zero(mesh.num_triangles());
    chi.head(20).setOnes();  // a penalised patch: the term stays as it was
    s->set_chi(chi);
    return s;
  }
};

// ρ → 0: Newton's first step is the Stokes solve and its residual is round-off.
TEST(NavierStokes, VanishingDensityGivesTheStokesSolution) {
  const PaperBox box;
  const auto stokes = box.fluid(0.0035, kDefaultSparseSolver);
  const auto ns = box.fluid(0.0035, kNavierStokesSolver);
  ns->set_navier_stokes({1e-14, 1e-10, 30});
  const FluidSolution& a = stokes->solve();
  const FluidSolution& b = ns->solve();
  EXPECT_EQ(ns->newton()->steps, 1);
  EXPECT_LT((a.v1 - b.v1).cwiseAbs().maxCoeff() + (a.v2 - b.v2).cwiseAbs().maxCoeff(), 1e-10 * 8.0);
  EXPECT_LT((a.p - b.p).cwiseAbs().maxCoeff(), 1e-10 * a.p.cwiseAbs().maxCoeff());
}

// The relative residuals fall quadratically (r_{k+1} ≤ C r_k², C from the first
// pair) to the tolerance, in a handful of steps; a second solve for a changed χ
// (a new ε) starts from the first solution.
TEST(NavierStokes, NewtonConvergesQuadraticallyAndWarmStarts) {
  const PaperBox box;
  const auto ns = box.fluid(0.0035, kNavierStokesSolver);
  ns->set_navier_stokes({0.02, 1e-11, 30});  // Re = ρ Vmax L1 / μ ≈ 19
  ns->solve();
  const std::vector<double> r = ns->newton()->residuals;
  std::ostringstream history;  // (std::string + to_string trips GCC 12's -Wstringop-overflow)
  for (double x : r) history << ' ' << x;
  ASSERT_GE(r.size(), 4u) << history.str();
  EXPECT_LE(r.back(), 1e-11);
  EXPECT_LE(ns->newton()->steps, 6) << history.str();
  EXPECT_EQ(ns->newton()->picard_steps, 0);
  const double C = r[2] / (r[1] * r[1]);
  for (std::size_t k = 2; k + 1 < r.size(); ++k)
    EXPECT_LT(r[k + 1], 10 * C * r[k] * r[k] + 1e-13) << "step " << k << ":" << history.str();
  const int first = ns->newton()->steps;
  ns->set_eps(2e-5);  // a new problem near the last one
  ns->solve();
  EXPECT_LE(ns->newton()->steps, first);
  EXPECT_LT(ns->newton()->residuals.front(), 0.1);  // it started from the first solution, not from rest
  EXPECT_EQ(ns->newton()->solves, 2);
}

// Far beyond where a steady flow is found from rest (Re ≈ 4700 here), Newton and
// Picard both fail: a SolverFailure naming the tolerance and the residuals, after
// at most newton_max_steps steps, never an endless loop.
TEST(NavierStokes, NoSteadyFlowFoundIsAFailureWithTheResidualHistory) {
  const PaperBox box;
  const auto ns = box.fluid(0.0035, kNavierStokesSolver);
  ns->set_navier_stokes({5.0, 1e-10, 12});
  try {
    ns->solve();
    FAIL() << "converged at Re 4700";
  } catch (const SolverFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("fluid.newton_tol"), std::string::npos) << what;
    EXPECT_NE(what.find("relative residuals 1,"), std::string::npos) << what;
    EXPECT_NE(what.find("Reynolds"), std::string::npos) << what;
  }
  EXPECT_EQ(ns->newton()->residuals.size(), 13u);  // the start and 12 steps
}

// The symmetric solver paths refuse Navier–Stokes's Jacobian, and the substructured
// factorisation refuses it by name before anything is solved.
TEST(NavierStokes, SymmetricPathsRefuseIt) {
  const PaperBox box;
  const auto ldlt = box.fluid(0.0035, kDefaultSparseSolver);
  ldlt->set_navier_stokes({1.0, 1e-10, 30});
  EXPECT_THROW(ldlt->solve(), SolverFailure);
  PenalisedStokes schur(box.mesh, 0.0035, 1e-5, [](const Point&) { return Point(0, 0); }, box.bc, kNavierStokesSolver,
                        FluidFactorization::schur);
  EXPECT_THROW(schur.set_navier_stokes({1.0, 1e-10, 30}), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::navier_stokes_test
