// P2 elasticity (structure.element = "P2", SPEC §11): a quadratic displacement is
// reproduced to round-off by the linear model (P2 holds quadratics: the patch test of
// the quadratic element), and manufactured solutions converge at P2's rates, L² 3 and
// H¹ 2, for the linear, Saint-Venant–Kirchhoff and neo-Hookean models, solved by the
// runs' ElasticContactSolver on the P2 space (Newton with the contact QP in every step,
// a floor far below), with Newton's quadratic convergence asserted; that solver
// against a plain Newton without contact written here.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "fem/quadrature.hpp"
#include "qp/active_set_solver.hpp"
#include "solid/contact_solver.hpp"
#include "solid/p2_elasticity.hpp"
#include "support/newton_order.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::p2_elasticity_test {
namespace {

const Lame kLame = Lame::from_young_poisson(3.0e5, 0.3);

std::vector<int> free_dofs(const P2Space& space, const char* clamp) {
  const std::vector<int> fixed = clamped_dofs(space, space.mesh().label(clamp));
  std::vector<int> out;
  for (int d = 0; d < 2 * space.num_nodes(); ++d)
    if (!std::binary_search(fixed.begin(), fixed.end(), d)) out.push_back(d);
  return out;
}

SparseMatrix restriction(int n, const std::vector<int>& free) {
  SparseMatrix P(n, static_cast<int>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) P.insert(free[k], static_cast<int>(k)) = 1.0;
  return P;
}

// Newton for f_int(u) = b with u = 0 on `clamp`, to ‖r‖∞ ≤ 1e-11 ‖b‖∞ (these meshes are
// stout: that is above their round-off): the independent reference of the solver.
Eigen::VectorXd plain_newton(const P2Space& space, const Material& m, const Eigen::VectorXd& b, const char* clamp) {
  const int n = 2 * space.num_nodes();
  const std::vector<int> free = free_dofs(space, clamp);
  const SparseMatrix P = restriction(n, free);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int step = 0; step < 30; ++step) {
    const Eigen::VectorXd r = P.transpose() * (internal_force(space, m, u) - b);
    if (r.lpNorm<Eigen::Infinity>() <= 1e-11 * b.lpNorm<Eigen::Infinity>()) return u;
    const SparseMatrix K = P.transpose() * tangent_stiffness(space, m, u) * P;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(K);
    u -= P * Eigen::VectorXd(ldlt.solve(r));
  }
  ADD_FAILURE() << "Newton did not converge";
  return u;
}

// The runs' solver on the P2 space of `mesh`: clamped on `clamp`, contact rows on the
// bottom against a floor far below (never active).
struct P2Solve {
  Eigen::VectorXd u;
  NewtonReport newton;
};
P2Solve solve_with_contact_solver(const Mesh& mesh, const Material& m, const Eigen::VectorXd& b, const char* clamp) {
  const auto owned = std::make_shared<const OwnedP2Space>(Mesh(mesh));
  Mesh nodal = nodal_mesh(owned->space);
  const std::vector<int> fixed = clamped_dofs(nodal, nodal.label(clamp));
  const int bottom = nodal.label("bottom");
  const FlatFoundation floor(-1e3);
  ActiveSetSolver qp;
  ElasticContactSolver solver(std::move(nodal), kLame, floor, bottom, fixed, qp, owned);
  solver.set_material(m);
  const ContactSolution s = solver.solve(b);
  EXPECT_EQ(s.qp.active_count(), 0);
  return {s.u, s.newton};
}

struct Errors {
  double l2 = 0, h1 = 0;
};

template <class Exact, class Gradient>
Errors p2_errors(const P2Space& space, const Eigen::VectorXd& u, Exact exact, Gradient gradient) {
  const int n = space.num_nodes();
  const TriangleRule rule = triangle_rule(8);
  Errors e;
  for (int t = 0; t < space.mesh().num_triangles(); ++t) {
    const P1Triangle T(space.mesh(), t);
    const auto& nodes = space.element(t);
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const P2Values v = p2_values(T, rule.lambda[q]);
      const Point x = T.point(rule.lambda[q]);
      Eigen::Vector2d uh = Eigen::Vector2d::Zero();
      Eigen::Matrix2d gh = Eigen::Matrix2d::Zero();
      for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 2; ++c) {
          uh[c] += u[dof(nodes[i], c, n)] * v.N[i];
          gh.row(c) += u[dof(nodes[i], c, n)] * v.grad.row(i);
        }
      e.l2 += rule.w[q] * T.area * (uh - exact(x)).squaredNorm();
      e.h1 += rule.w[q] * T.area * (gh - gradient(x)).squaredNorm();
    }
  }
  return {std::sqrt(e.l2), std::sqrt(e.h1)};
}

// The load of a stress field S(x) (σ or P) in equilibrium with u = 0 on the left:
// f = −div S by central differences (step h), the traction S N on the other sides.
Eigen::VectorXd load_of(const P2Space& space, const std::function<Matrix2(const Point&)>& S, double h,
                        int volume_degree, int edge_points) {
  const VectorField body = [&](const Point& x) -> Point {
    const Matrix2 dx = (S(x + Point(h, 0)) - S(x - Point(h, 0))) / (2 * h);
    const Matrix2 dy = (S(x + Point(0, h)) - S(x - Point(0, h))) / (2 * h);
    return -(dx.col(0) + dy.col(1));
  };
  Eigen::VectorXd b = assemble_volume_load(space, body, volume_degree);
  const std::pair<const char*, Point> sides[] = {{"right", {1, 0}}, {"top", {0, 1}}, {"bottom", {0, -1}}};
  for (const auto& [name, N] : sides) {
    const Point normal = N;  // a structured binding: clang cannot capture it
    b += assemble_surface_load(space, space.mesh().label(name), [&, normal](const Point& x) { return Point(S(x) * normal); },
                               edge_points);
  }
  return b;
}

// u = x (0.1 x + 0.05 y, −0.08 x + 0.03 y): quadratic and zero on x = 0. Its σ is linear,
// f = −div σ constant, and the traction σN on the other sides linear: all exact.
TEST(P2Elasticity, ReproducesAQuadraticDisplacement) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 4, 2);
  const P2Space space(mesh);
  auto exact = [](const Point& x) { return Eigen::Vector2d(x.x() * (0.1 * x.x() + 0.05 * x.y()), x.x() * (-0.08 * x.x() + 0.03 * x.y())); };
  auto gradient = [](const Point& x) {
    Eigen::Matrix2d g;
    g << 0.2 * x.x() + 0.05 * x.y(), 0.05 * x.x(), -0.16 * x.x() + 0.03 * x.y(), 0.03 * x.x();
    return g;
  };
  auto sigma = [&](const Point& x) {
    const Eigen::Matrix2d g = gradient(x);
    return Eigen::Matrix2d(kLame.lambda * g.trace() * Eigen::Matrix2d::Identity() + kLame.mu * (g + g.transpose()));
  };
  // σ is linear: central differences are exact up to round-off.
  const Eigen::VectorXd b = load_of(space, sigma, 1e-5, 2, 3);
  const Eigen::VectorXd u = solve_with_contact_solver(mesh, {MaterialModel::linear, kLame}, b, "left").u;
  const Errors e = p2_errors(space, u, exact, gradient);
  EXPECT_LT(e.l2, 1e-9);
  EXPECT_LT(e.h1, 1e-8);
}

// The manufactured solution of hyperelastic_test.cpp on (0,1)×(0,0.5), clamped at x = 0.
constexpr double sa = 1.3, sb = 0.7, sc = 1.1, sd = 0.9, kAmplitude = 0.2;

Eigen::Vector2d exact(const Point& x) {
  return kAmplitude * Eigen::Vector2d(std::sin(sa * x.x()) * std::cos(sb * x.y()), std::sin(sc * x.x()) * std::sin(sd * x.y()));
}
Eigen::Matrix2d gradient(const Point& x) {
  Eigen::Matrix2d g;
  g << sa * std::cos(sa * x.x()) * std::cos(sb * x.y()), -sb * std::sin(sa * x.x()) * std::sin(sb * x.y()),
      sc * std::cos(sc * x.x()) * std::sin(sd * x.y()), sd * std::sin(sc * x.x()) * std::cos(sd * x.y());
  return kAmplitude * g;
}

struct MmsResult {
  Errors errors;
  NewtonReport newton;
};

MmsResult solve_mms(const P2Space& space, const Material& m) {
  auto P = [&](const Point& x) { return m.stress(Matrix2::Identity() + gradient(x)); };
  const Eigen::VectorXd b = load_of(space, P, 1e-4, 6, 4);
  const P2Solve s = solve_with_contact_solver(space.mesh(), m, b, "left");
  return {p2_errors(space, s.u, exact, gradient), s.newton};
}

TEST(P2Elasticity, ManufacturedSolutionsConvergeAtTheP2RatesWithQuadraticNewton) {
  for (MaterialModel model : {MaterialModel::linear, MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    std::vector<double> l2, h1;
    NewtonReport finest;
    for (int n : {8, 16, 32, 64}) {
      const Mesh mesh = testing::structured_rectangle(1.0, 0.5, n, n / 2);
      const MmsResult r = solve_mms(P2Space(mesh), {model, kLame});
      l2.push_back(r.errors.l2), h1.push_back(r.errors.h1);
      finest = r.newton;
    }
    for (std::size_t k = 0; k + 1 < l2.size(); ++k) {
      const double r_l2 = std::log2(l2[k] / l2[k + 1]), r_h1 = std::log2(h1[k] / h1[k + 1]);
      std::printf("model %d n %3d  L2 %.3e (rate %.3f)  H1 %.3e (rate %.3f)\n", static_cast<int>(model), 16 << k,
                  l2[k + 1], r_l2, h1[k + 1], r_h1);
      EXPECT_GE(r_l2, 2.85) << "L2, model " << static_cast<int>(model) << ", refinement " << k;
      EXPECT_GE(r_h1, 1.9) << "H1, model " << static_cast<int>(model) << ", refinement " << k;
    }
    if (model == MaterialModel::linear) continue;
    for (double x : finest.history) std::printf("  newton residual %.3e\n", x);
    testing::expect_quadratic(finest.history);
    EXPECT_LE(finest.residual, 1e-10);
    EXPECT_EQ(finest.load_steps, 1);
  }
}

// The solver's P2 Newton (free-dof assembly, QP steps) lands where a plain Newton on the
// whole-space f_int and K_T does.
TEST(P2Elasticity, TheContactSolversNewtonAgreesWithAPlainNewton) {
  const Mesh mesh = testing::structured_rectangle(1.0, 0.5, 8, 4);
  const P2Space space(mesh);
  for (MaterialModel model : {MaterialModel::saint_venant_kirchhoff, MaterialModel::neo_hookean}) {
    const Material m{model, kLame};
    auto P = [&](const Point& x) { return m.stress(Matrix2::Identity() + gradient(x)); };
    const Eigen::VectorXd b = load_of(space, P, 1e-4, 6, 4);
    const Eigen::VectorXd reference = plain_newton(space, m, b, "left");
    const Eigen::VectorXd u = solve_with_contact_solver(mesh, m, b, "left").u;
    EXPECT_LT((u - reference).cwiseAbs().maxCoeff(), 1e-9 * reference.cwiseAbs().maxCoeff()) << static_cast<int>(model);
  }
}

}  // namespace
}  // namespace fsi::p2_elasticity_test
