// The hyperelastic structure (SPEC §11): the materials' stress and tangent against
// finite differences of their energy and stress, the tangent at rest against A_S,
// the frame indifference of a rigid rotation (and the linear model's lack of it), a
// patch test through Newton, manufactured solutions at the P1 rates with Newton's
// quadratic convergence, and Newton with contact against the linear limit.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>

#include "common/errors.hpp"
#include "qp/active_set_solver.hpp"
#include "qp/ipopt_solver.hpp"
#include "solid/contact_solver.hpp"
#include "solid/free_dof_assembly.hpp"
#include "solid/hyperelastic.hpp"
#include "support/newton_order.hpp"
#include "support/norms.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::hyperelastic_test {
namespace {

const Lame kLame = Lame::from_young_poisson(3.0e5, 0.3);
const MaterialModel kNonlinear[] = {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean};
const MaterialModel kAll[] = {MaterialModel::linear, MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean};

Matrix2 some_F() {
  Matrix2 F;
  F << 1.15, 0.22, -0.17, 0.93;
  return F;
}

TEST(Hyperelastic, StressIsTheEnergysDerivativeAndItsDerivativeTheTangent) {
  const double d = 1e-6;
  for (MaterialModel model : kAll) {
    const Material m{model, kLame};
    const Matrix2 F = some_F();
    Matrix2 dF;
    dF << 0.3, -0.7, 0.4, 0.2;
    const double dW = (m.energy(F + d * dF) - m.energy(F - d * dF)) / (2 * d);
    const double scale = kLame.mu;
    EXPECT_NEAR(dW, (m.stress(F).array() * dF.array()).sum(), 1e-7 * scale) << static_cast<int>(model);
    const Matrix2 dP = (m.stress(F + d * dF) - m.stress(F - d * dF)) / (2 * d);
    EXPECT_LT((dP - m.stress_derivative(F, dF)).norm(), 1e-7 * scale) << static_cast<int>(model);
  }
}

TEST(Hyperelastic, TheTangentAtRestIsA_S) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 6, 3);
  const SparseMatrix A = assemble_elasticity(mesh, kLame);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2 * mesh.num_vertices());
  for (MaterialModel model : kNonlinear) {
    const SparseMatrix K = tangent_stiffness(mesh, {model, kLame}, zero);
    EXPECT_LT(Eigen::MatrixXd(K - A).cwiseAbs().maxCoeff(), 1e-10 * Eigen::MatrixXd(A).cwiseAbs().maxCoeff());
    EXPECT_LT(internal_force(mesh, {model, kLame}, zero).norm(), 1e-12);
  }
}

TEST(Hyperelastic, TheTangentIsTheInternalForcesDerivative) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 4, 2);
  const int n = 2 * mesh.num_vertices();
  Eigen::VectorXd u(n), du(n);
  for (int i = 0; i < n; ++i) u[i] = 0.05 * std::sin(1.7 * i), du[i] = std::cos(0.9 * i);
  const double d = 1e-6;
  for (MaterialModel model : kNonlinear) {
    const Material m{model, kLame};
    const Eigen::VectorXd fd = (internal_force(mesh, m, u + d * du) - internal_force(mesh, m, u - d * du)) / (2 * d);
    const Eigen::VectorXd Kdu = tangent_stiffness(mesh, m, u) * du;
    EXPECT_LT((fd - Kdu).norm(), 1e-6 * Kdu.norm()) << static_cast<int>(model);
    const SparseMatrix K = tangent_stiffness(mesh, m, u);
    EXPECT_LT(Eigen::MatrixXd(K - SparseMatrix(K.transpose())).norm(), 1e-9 * Eigen::MatrixXd(K).norm());
  }
}

// The Newton loop's assembly onto the free dofs (FreeDofAssembler) is the plain
// assembly (checked above against finite differences) restricted to them.
TEST(Hyperelastic, TheFreeDofAssemblyIsThePlainOneRestricted) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 4, 2);
  const int n = 2 * mesh.num_vertices();
  const std::vector<int> clamped = clamped_dofs(mesh, mesh.label("left"));
  std::vector<int> free;
  for (int d = 0; d < n; ++d)
    if (!std::binary_search(clamped.begin(), clamped.end(), d)) free.push_back(d);
  SparseMatrix P(n, static_cast<int>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) P.insert(free[k], static_cast<int>(k)) = 1.0;
  const SparseMatrix pattern = P.transpose() * assemble_elasticity(mesh, kLame) * P;
  const FreeDofAssembler assembler(mesh, free, pattern);
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) u[i] = 0.05 * std::sin(1.7 * i);
  for (MaterialModel model : kNonlinear) {
    const Material m{model, kLame};
    SparseMatrix K = pattern;
    assembler.tangent(m, u, K);
    const SparseMatrix expected = P.transpose() * tangent_stiffness(mesh, m, u) * P;
    EXPECT_LT(Eigen::MatrixXd(K - expected).cwiseAbs().maxCoeff(), 1e-10 * Eigen::MatrixXd(expected).cwiseAbs().maxCoeff())
        << static_cast<int>(model);
    const Eigen::VectorXd f = internal_force(mesh, m, u);
    EXPECT_LT((assembler.force(m, u) - Eigen::VectorXd(f(free))).norm(), 1e-12 * f.norm()) << static_cast<int>(model);
  }
}

// u = (R − I) X, a rotation by 0.6 rad: no strain, so no stress and no internal force
// for SVK and neo-Hookean; the linear model sees a strain of 1 − cos 0.6 = 0.175.
TEST(Hyperelastic, ARigidRotationIsStressFreeOnlyForTheNonlinearModels) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 6, 3);
  const int nv = mesh.num_vertices();
  const double a = 0.6;
  Matrix2 R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  Eigen::VectorXd u(2 * nv);
  for (int v = 0; v < nv; ++v) {
    const Point d = (R - Matrix2::Identity()) * mesh.vertices[v];
    u[v] = d.x(), u[nv + v] = d.y();
  }
  for (MaterialModel model : kNonlinear) {
    const Material m{model, kLame};
    EXPECT_LT(m.stress(R).norm(), 1e-10 * kLame.mu);
    EXPECT_LT(internal_force(mesh, m, u).cwiseAbs().maxCoeff(), 1e-10 * kLame.mu);
    EXPECT_NEAR(stored_energy(mesh, m, u), 0.0, 1e-12 * kLame.mu);
  }
  const Material linear{MaterialModel::linear, kLame};
  EXPECT_GT(linear.stress(R).norm(), 0.1 * kLame.mu);
  EXPECT_GT(internal_force(mesh, linear, u).cwiseAbs().maxCoeff(), 1e-3 * kLame.mu);
}

// A solver on `mesh` clamped on `clamp`, contact rows on `contact` against a floor
// far below (never active): the equilibrium problem alone.
struct Free {
  Free(const Mesh& mesh, MaterialModel model, const char* clamp = "left", const char* contact = "bottom")
      : floor(-1e3), solver(mesh, kLame, floor, mesh.label(contact), clamped_dofs(mesh, mesh.label(clamp)), qp) {
    solver.set_material({model, kLame});
  }
  FlatFoundation floor;
  ActiveSetSolver qp;
  ElasticContactSolver solver;
};

// The affine u = (F0 − I) X with F0 − I = [[0.2, 0], [−0.15, 0]] vanishes on x = 0;
// its first Piola–Kirchhoff stress P0 is constant, so the traction P0 N on the other
// sides is all the load. P1 holds affine fields: Newton must return it exactly.
TEST(Hyperelastic, PatchTestThroughNewton) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 5, 3);
  const int nv = mesh.num_vertices();
  Matrix2 F0;
  F0 << 1.2, 0.0, -0.15, 1.0;
  for (MaterialModel model : kNonlinear) {
    const Matrix2 P0 = Material{model, kLame}.stress(F0);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * nv);
    const std::pair<const char*, Point> sides[] = {{"right", {1, 0}}, {"top", {0, 1}}, {"bottom", {0, -1}}};
    for (const auto& [name, N] : sides) {
      const Point t = P0 * N;
      b += assemble_surface_load(mesh, mesh.label(name), [t](const Point&) { return t; }, 2);
    }
    Free f(mesh, model);
    const ContactSolution s = f.solver.solve(b);
    double error = 0;
    for (int v = 0; v < nv; ++v) {
      const Point exact = (F0 - Matrix2::Identity()) * mesh.vertices[v];
      error = std::max(error, (Point(s.u[v], s.u[nv + v]) - exact).norm());
    }
    EXPECT_LT(error, 1e-9 * 0.2) << static_cast<int>(model);
    EXPECT_LE(s.newton.residual, 1e-10);
    EXPECT_EQ(s.newton.load_steps, 1);
  }
}

// u = s (sin(a x) cos(b y), sin(c x) sin(d y)) on (0,1)×(0,0.5), clamped at x = 0,
// the traction P N on the other sides, f = −Div P(F(u)) (by central differences of P
// in X: their error, ~1e-9 of P, is far below the discretisation's).
constexpr double sa = 1.3, sb = 0.7, sc = 1.1, sd = 0.9, kAmplitude = 0.2;

Eigen::VectorXd exact(const Point& x) {
  return kAmplitude * Eigen::Vector2d(std::sin(sa * x.x()) * std::cos(sb * x.y()), std::sin(sc * x.x()) * std::sin(sd * x.y()));
}
Eigen::MatrixXd gradient(const Point& x) {
  Eigen::Matrix2d g;
  g << sa * std::cos(sa * x.x()) * std::cos(sb * x.y()), -sb * std::sin(sa * x.x()) * std::sin(sb * x.y()),
      sc * std::cos(sc * x.x()) * std::sin(sd * x.y()), sd * std::sin(sc * x.x()) * std::cos(sd * x.y());
  return kAmplitude * g;
}

struct MmsResult {
  testing::Errors errors;
  NewtonReport newton;
};

MmsResult solve_mms(const Mesh& mesh, MaterialModel model) {
  const Material m{model, kLame};
  auto P = [&](const Point& x) { return m.stress(Matrix2::Identity() + Matrix2(gradient(x))); };
  const double h = 1e-4;
  const VectorField body = [&](const Point& x) -> Point {
    const Matrix2 dPdx = (P(x + Point(h, 0)) - P(x - Point(h, 0))) / (2 * h);
    const Matrix2 dPdy = (P(x + Point(0, h)) - P(x - Point(0, h))) / (2 * h);
    return -(dPdx.col(0) + dPdy.col(1));
  };
  Eigen::VectorXd b = assemble_volume_load(mesh, body, 6);
  const std::pair<const char*, Point> sides[] = {{"right", {1, 0}}, {"top", {0, 1}}, {"bottom", {0, -1}}};
  for (const auto& [name, N] : sides) {
    const Point normal = N;  // a structured binding: clang cannot capture it
    b += assemble_surface_load(mesh, mesh.label(name), [&, normal](const Point& x) { return Point(P(x) * normal); }, 4);
  }
  Free f(mesh, model);
  const ContactSolution s = f.solver.solve(b);
  EXPECT_EQ(s.qp.active_count(), 0);
  return {testing::p1_errors(mesh, s.u, 2, exact, gradient), s.newton};
}

TEST(Hyperelastic, ManufacturedSolutionsConvergeAtTheP1RatesWithQuadraticNewton) {
  for (MaterialModel model : kNonlinear) {
    std::vector<double> l2, h1;
    NewtonReport finest;
    for (int n : {16, 32, 64, 128}) {
      const MmsResult r = solve_mms(testing::structured_rectangle(1.0, 0.5, n, n / 2), model);
      l2.push_back(r.errors.l2);
      h1.push_back(r.errors.h1);
      finest = r.newton;
    }
    for (std::size_t k = 0; k + 1 < l2.size(); ++k) {
      const double r_l2 = std::log2(l2[k] / l2[k + 1]), r_h1 = std::log2(h1[k] / h1[k + 1]);
      std::printf("model %d n %4d  L2 %.3e (rate %.3f)  H1 %.3e (rate %.3f)\n", static_cast<int>(model), 32 << k,
                  l2[k + 1], r_l2, h1[k + 1], r_h1);
      EXPECT_GE(r_l2, 1.9) << "L2 rate, refinement " << k;
      EXPECT_GE(r_h1, 0.9) << "H1 rate, refinement " << k;
    }
    for (double x : finest.history) std::printf("  newton residual %.3e\n", x);
    testing::expect_quadratic(finest.history);
    EXPECT_LE(finest.residual, 1e-10);
    EXPECT_EQ(finest.load_steps, 1);
  }
}

// Newton with contact through IPOPT (each step one IPOPT QP) lands where the
// active-set solver does.
TEST(Hyperelastic, NewtonWithContactAgreesBetweenTheActiveSetSolverAndIpopt) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.1, 40, 4);
  const FlatFoundation floor(-0.01);
  const std::vector<int> clamp = clamped_dofs(mesh, mesh.label("left"));
  const Eigen::VectorXd b = assemble_volume_load(mesh, [](const Point&) { return Point(0, -4e3); }, 1);
  ActiveSetSolver active_set;
  IpoptSolver ipopt;
  Eigen::VectorXd u[2];
  QpSolver* solvers[2] = {&active_set, &ipopt};
  for (int k = 0; k < 2; ++k) {
    ElasticContactSolver s(mesh, kLame, floor, mesh.label("bottom"), clamp, *solvers[k]);
    s.set_material({MaterialModel::neo_hookean, kLame});
    const ContactSolution c = s.solve(b);
    ASSERT_GE(c.qp.active_count(), 1) << solvers[k]->name();
    EXPECT_LE(c.newton.residual, 1e-10) << solvers[k]->name();
    u[k] = c.u;
  }
  EXPECT_LT((u[0] - u[1]).cwiseAbs().maxCoeff(), 1e-8 * u[0].cwiseAbs().maxCoeff());
}

// Saint-Venant–Kirchhoff under a load a thousand times Turek–Hron's (the flag folded
// onto itself): Newton converges, to a state with folded triangles (det F ≤ 0), which
// is said as a failure, not returned.
TEST(Hyperelastic, AFoldedSaintVenantKirchhoffEquilibriumIsAFailure) {
  const Mesh mesh = testing::structured_rectangle(0.35, 0.02, 44, 3);
  const Lame lame = Lame::from_young_poisson(1.4e6, 0.4);
  const FlatFoundation far(-10);
  ActiveSetSolver qp;
  ElasticContactSolver svk(mesh, lame, far, mesh.label("bottom"), clamped_dofs(mesh, mesh.label("left")), qp);
  svk.set_material({MaterialModel::saint_venant_kirchhoff, lame});
  const Eigen::VectorXd b = assemble_volume_load(mesh, [](const Point&) { return Point(0, -2e6); }, 1);
  try {
    svk.solve(b);
    ADD_FAILURE() << "a folded equilibrium was returned";
  } catch (const SolverFailure& e) {
    EXPECT_NE(std::string(e.what()).find("folds"), std::string::npos) << e.what();
  }
}

// A cantilever pressed onto a floor by its weight: Newton with contact gives a
// feasible state with multipliers ≥ 0 and KKT to round-off; for loads → 0 its
// displacement tends to the linear model's (relative difference ∝ the load).
TEST(Hyperelastic, NewtonWithContactTendsToTheLinearAnswerForSmallLoads) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.1, 40, 4);
  const FlatFoundation floor(-0.01);
  const std::vector<int> clamp = clamped_dofs(mesh, mesh.label("left"));
  std::vector<double> difference;
  for (double scale : {1.0, 0.5, 0.25}) {
    const Eigen::VectorXd b = assemble_volume_load(mesh, [scale](const Point&) { return Point(0, -4e3 * scale); }, 1);
    ActiveSetSolver qp_linear, qp_nonlinear;
    ElasticContactSolver linear(mesh, kLame, FlatFoundation(-0.01 * scale), mesh.label("bottom"), clamp, qp_linear);
    ElasticContactSolver svk(mesh, kLame, FlatFoundation(-0.01 * scale), mesh.label("bottom"), clamp, qp_nonlinear);
    svk.set_material({MaterialModel::saint_venant_kirchhoff, kLame});
    const ContactSolution a = linear.solve(b), s = svk.solve(b);
    ASSERT_GE(s.qp.active_count(), 1) << "the beam should touch the floor";
    EXPECT_LT(s.qp.kkt.max(), 1e-9);
    EXPECT_GE(s.qp.alpha.minCoeff(), 0.0);
    const Eigen::VectorXd slack = svk.contact().C_S * s.u - svk.contact().c_lb;
    EXPECT_GE(slack.minCoeff(), -1e-12 * slack.cwiseAbs().maxCoeff());
    EXPECT_LE(s.newton.residual, 1e-10);
    difference.push_back((s.u - a.u).norm() / a.u.norm());
  }
  // Geometry scales with the load here (floor and load together), so the nonlinear
  // part of the answer shrinks like the load: the difference halves with it.
  for (std::size_t k = 0; k + 1 < difference.size(); ++k) {
    std::printf("load scale %g: relative difference %.3e\n", 1.0 / (1 << k), difference[k]);
    EXPECT_NEAR(difference[k] / difference[k + 1], 2.0, 0.3) << k;
  }
}

}  // namespace
}  // namespace fsi::hyperelastic_test
