// Random strictly convex QPs for the solver tests: min ½xᵀAx − bᵀx s.t. Cx ≥ c.
#pragma once

#include <Eigen/Dense>
#include <random>

#include "qp/qp_problem.hpp"

namespace fsi::testing {

struct RandomQp {
  SparseMatrix A, C;
  Eigen::VectorXd b, c;
};

// A = MᵀM + I (SPD), sparse-ish C with full row rank, bounds that make some rows bind.
inline RandomQp random_qp(int n, int m, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::MatrixXd M(n, n), C(m, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = (std::abs(i - j) <= 2) ? N(gen) : 0.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) C(i, j) = (j % m == i || (j + 1) % m == i) ? N(gen) : 0.0;
  RandomQp q;
  q.A = (M.transpose() * M + Eigen::MatrixXd::Identity(n, n)).sparseView();
  q.C = C.sparseView();
  q.b = Eigen::VectorXd::NullaryExpr(n, [&] { return N(gen); });
  // Bounds around the unconstrained minimiser's values: about half the rows bind.
  const Eigen::VectorXd x0 = Eigen::MatrixXd(q.A).llt().solve(q.b);
  q.c = C * x0 + Eigen::VectorXd::NullaryExpr(m, [&] { return N(gen); });
  return q;
}

}  // namespace fsi::testing
