// Sparse direct solvers for the condensed Stokes system, behind one interface so
// they can be measured against each other (docs/performance.md). The pattern is
// analysed once; only the values change when χ does.
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <string>

namespace fsi {

class SparseDirectSolver {
 public:
  virtual ~SparseDirectSolver() = default;
  // Symbolic analysis (ordering) for the pattern of A; done once.
  virtual void analyze(const Eigen::SparseMatrix<double>& A) = 0;
  // Numeric factorisation of A (same pattern as analysed). Throws on failure.
  virtual void factorize(const Eigen::SparseMatrix<double>& A) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& rhs) = 0;
  virtual std::string name() const = 0;
};

// "umfpack" (LU), "cholmod-ldlt" (LDLᵀ of the quasi-definite system), ...
std::unique_ptr<SparseDirectSolver> make_sparse_solver(const std::string& name);

}  // namespace fsi
