// The contact QP solvers against an independent one: for small problems the unique
// minimiser is found by enumerating every active set and keeping the one that
// satisfies the KKT conditions.
#include <gtest/gtest.h>

#include "qp/active_set_solver.hpp"
#include "qp/ipopt_solver.hpp"
#include "qp/random_qp.hpp"

namespace fsi::qp_solvers_test {
namespace {

using testing::random_qp;
using testing::RandomQp;

// Tries all 2^m active sets: solve [A −C_Aᵀ; C_A 0][x; α_A] = [b; c_A] and keep the
// one with α_A ≥ 0 and Cx ≥ c.
Eigen::VectorXd brute_force(const RandomQp& q, Eigen::VectorXd& alpha) {
  const Eigen::MatrixXd A(q.A), C(q.C);
  const int n = static_cast<int>(A.rows()), m = static_cast<int>(C.rows());
  for (int mask = 0; mask < (1 << m); ++mask) {
    std::vector<int> act;
    for (int i = 0; i < m; ++i)
      if (mask & (1 << i)) act.push_back(i);
    const int k = static_cast<int>(act.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + k, n + k);
    Eigen::VectorXd rhs(n + k);
    K.topLeftCorner(n, n) = A;
    rhs.head(n) = q.b;
    for (int a = 0; a < k; ++a) {
      K.block(0, n + a, n, 1) = -C.row(act[a]).transpose();
      K.block(n + a, 0, 1, n) = C.row(act[a]);
      rhs[n + a] = q.c[act[a]];
    }
    const Eigen::VectorXd sol = K.fullPivLu().solve(rhs);
    const Eigen::VectorXd x = sol.head(n);
    Eigen::VectorXd al = Eigen::VectorXd::Zero(m);
    for (int a = 0; a < k; ++a) al[act[a]] = sol[n + a];
    if (al.minCoeff() >= -1e-10 && (C * x - q.c).minCoeff() >= -1e-10) {
      alpha = al;
      return x;
    }
  }
  ADD_FAILURE() << "no active set satisfies the KKT conditions";
  return {};
}

class QpSolvers : public ::testing::TestWithParam<unsigned> {};

TEST_P(QpSolvers, AgreeWithEnumerationOfActiveSets) {
  const RandomQp q = random_qp(40, 8, GetParam());
  Eigen::VectorXd alpha_exact;
  const Eigen::VectorXd x_exact = brute_force(q, alpha_exact);
  const double scale = x_exact.norm(), alpha_scale = std::max(alpha_exact.norm(), 1e-12);

  ActiveSetSolver pdas;
  pdas.set_operator(q.A, q.C);
  const QpResult r = pdas.solve(q.b, q.c);
  EXPECT_LT((r.x - x_exact).norm(), 1e-10 * scale);
  EXPECT_LT((r.alpha - alpha_exact).norm(), 1e-9 * alpha_scale);
  EXPECT_LT(r.kkt.max(), 1e-12);

  IpoptSolver ipopt;
  ipopt.set_operator(q.A, q.C);
  const QpResult s = ipopt.solve(q.b, q.c);
  EXPECT_LT((s.x - x_exact).norm(), 1e-8 * scale);
  EXPECT_LT((s.alpha - alpha_exact).norm(), 1e-6 * alpha_scale);
  EXPECT_EQ(s.active, r.active);
}

TEST_P(QpSolvers, LawsonHansonFallbackReachesTheSameMinimiser) {
  const RandomQp q = random_qp(40, 8, GetParam());
  Eigen::VectorXd alpha_exact;
  const Eigen::VectorXd x_exact = brute_force(q, alpha_exact);
  ActiveSetSolver solver;
  solver.max_iterations = 0;  // no PDAS step at all: Lawson–Hanson does everything
  solver.set_operator(q.A, q.C);
  const QpResult r = solver.solve(q.b, q.c);
  EXPECT_TRUE(solver.used_fallback());
  EXPECT_LT((r.x - x_exact).norm(), 1e-10 * x_exact.norm());
  EXPECT_LT(r.kkt.max(), 1e-12);
}

TEST_P(QpSolvers, WarmStartFromTheSolutionTakesOneIteration) {
  const RandomQp q = random_qp(40, 8, GetParam());
  ActiveSetSolver solver;
  solver.set_operator(q.A, q.C);
  const QpResult cold = solver.solve(q.b, q.c);
  const QpResult warm = solver.solve(q.b, q.c, &cold);
  EXPECT_EQ(warm.iterations, 1);
  EXPECT_LT((warm.x - cold.x).norm(), 1e-12 * cold.x.norm());
}

INSTANTIATE_TEST_SUITE_P(Seeds, QpSolvers, ::testing::Range(1u, 13u));

TEST(QpSolvers, ReportIterationsOnTheProgressLine) {
  const RandomQp q = random_qp(20, 6, 7);
  ActiveSetSolver solver;
  std::vector<std::string> lines;
  solver.progress = [&](const std::string& l) { lines.push_back(l); };
  solver.set_operator(q.A, q.C);
  const QpResult r = solver.solve(q.b, q.c);
  EXPECT_EQ(static_cast<int>(lines.size()), r.iterations);
}

// A result carries α clamped to ≥ 0, but its dual feasibility is that of the
// multipliers the solver computed: the force of a negative one, relative to the
// force balance ‖A‖∞‖x‖∞ + ‖b‖∞ + ‖Cᵀα‖∞. (Both solvers once clamped first, which
// reported 0 whatever the solver produced.) The other residuals are the clamped α's.
TEST(QpSolvers, DualFeasibilityMeasuresTheMultipliersBeforeClamping) {
  const RandomQp q = random_qp(40, 8, 1);
  ActiveSetSolver solver;
  solver.set_operator(q.A, q.C);
  const QpResult r = solver.solve(q.b, q.c);
  Eigen::Index inactive = 0;
  while (r.active[inactive]) ++inactive;
  Eigen::VectorXd raw = r.alpha;
  raw[inactive] = -1e-3 * r.alpha.maxCoeff();

  const KktResiduals k = solver_kkt_residuals(q.A, q.b, q.C, q.c, r.x, raw);
  const Eigen::MatrixXd A(q.A), C(q.C);
  const double balance = A.cwiseAbs().rowwise().sum().maxCoeff() * r.x.lpNorm<Eigen::Infinity>() +
                         q.b.lpNorm<Eigen::Infinity>() +
                         (C.transpose() * r.alpha).lpNorm<Eigen::Infinity>();
  const double force = -raw[inactive] * C.row(inactive).cwiseAbs().maxCoeff();
  EXPECT_NEAR(k.dual_feasibility, force / balance, 1e-12 * force / balance);
  EXPECT_GT(k.max(), solver.kkt_tolerance);
  const KktResiduals clamped = kkt_residuals(q.A, q.b, q.C, q.c, r.x, r.alpha);
  EXPECT_EQ(k.stationarity, clamped.stationarity);
  EXPECT_EQ(k.complementarity, clamped.complementarity);
  EXPECT_EQ(clamped.dual_feasibility, 0.0);
}

TEST(QpSolvers, RejectAnIndefiniteOperator) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  A(2, 2) = -1.0;
  SparseMatrix C(1, 4);
  C.insert(0, 0) = 1.0;
  ActiveSetSolver solver;
  EXPECT_THROW(solver.set_operator(A.sparseView(), C), QpError);
}

}  // namespace
}  // namespace fsi::qp_solvers_test
