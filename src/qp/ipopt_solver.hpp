// The contact QP through IPOPT (the paper's solver, eq. 20–22), as an independent
// check of the active-set solver and for users who want the paper's setup.
#pragma once

#include "qp/qp_problem.hpp"

namespace fsi {

class IpoptSolver final : public QpSolver {
 public:
  void set_operator(const SparseMatrix& A, const SparseMatrix& C) override;
  QpResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                 const QpResult* warm = nullptr) override;
  std::string name() const override { return "ipopt"; }

  double tolerance = 1e-15;  // IPOPT's `tol`, on the scaled problem
  int max_iterations = 500;

 private:
  SparseMatrix A_, C_;
};

}  // namespace fsi
