#include "fluid/sparse_solver.hpp"

#include <Eigen/UmfPackSupport>
#include <stdexcept>

namespace fsi {
namespace {

class UmfpackSolver final : public SparseDirectSolver {
 public:
  void analyze(const Eigen::SparseMatrix<double>& A) override { lu_.analyzePattern(A); }
  void factorize(const Eigen::SparseMatrix<double>& A) override {
    lu_.factorize(A);
    if (lu_.info() != Eigen::Success)
      throw std::runtime_error("UMFPACK could not factorise the Stokes matrix (singular?)");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) override { return lu_.solve(rhs); }
  std::string name() const override { return "umfpack"; }

 private:
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
};

}  // namespace

std::unique_ptr<SparseDirectSolver> make_sparse_solver(const std::string& name) {
  if (name == "umfpack") return std::make_unique<UmfpackSolver>();
  throw std::invalid_argument("unknown sparse solver '" + name + "'");
}

}  // namespace fsi
