// The contact QP through IPOPT (the paper's solver, eq. 20–22), as an independent
// check of the active-set solver and for users who want the paper's setup.
// Any finite data gives a solution within the KKT tolerance or a QpError: non-finite
// data, a problem whose scaled form is not representable, IPOPT's failures, its
// exceptions and its restoration phase (a crash in IPOPT 3.11, see the .cpp) are
// all refused (tests/qp/qp_robustness_test.cpp).
#pragma once

#include "qp/qp_problem.hpp"

namespace fsi {

class IpoptSolver final : public QpSolver {
 public:
  void set_operator(const SparseMatrix& A, const SparseMatrix& C) override;
  void set_constraints(const SparseMatrix& C) override;
  QpResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                 const QpResult* warm = nullptr) override;
  std::string name() const override { return "ipopt"; }

  double tolerance = 1e-15;  // IPOPT's `tol`, on the scaled problem
  int max_iterations = 500;

 private:
  SparseMatrix A_, C_;
};

}  // namespace fsi
