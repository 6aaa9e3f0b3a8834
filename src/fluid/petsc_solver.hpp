// fluid.linear_solver = "petsc-mumps" | "petsc-iterative" (SPEC §13): the fluid's
// linear systems through PETSc, behind the same interface as the direct solvers
// (sparse_solver.hpp), PETSc itself in a plugin loaded on first use
// (petsc_plugin.hpp). An iterative "factorisation" is the preconditioner's set-up;
// each solve starts from the last solution (a warm start) and records its iterations.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "fluid/sparse_solver.hpp"

namespace fsi {

struct PetscPlugin;

class PetscSolver final : public SparseDirectSolver {
 public:
  // name: "petsc-mumps" or "petsc-iterative". Loads the plugin and initialises PETSc
  // (SolverFailure if this build has none, or it cannot start).
  PetscSolver(const std::string& name, const LinearSolverOptions& options);
  ~PetscSolver() override;
  std::string name() const override { return name_; }
  bool needs_symmetry() const override { return false; }
  void describe_system(std::vector<char> is_pressure, bool symmetric) override {
    is_pressure_ = std::move(is_pressure);
    symmetric_ = symmetric;
  }
  bool wants_pressure_mass() const override { return iterative_ && options_.schur_mass; }
  bool wants_locality_order() const override { return ranks_ > 1; }
  void set_locality_order(std::vector<int> rank) override { locality_ = std::move(rank); }
  void set_pressure_mass(Eigen::SparseMatrix<double> M) override { pressure_mass_ = std::move(M); }
  double residual_tolerance() const override;

 protected:
  // On several ranks, the unknowns renumbered first (order_).
  void analyze_pattern(const Eigen::SparseMatrix<double>& A) override;
  void factorize_values(const Eigen::SparseMatrix<double>& A) override;
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) override;

 private:
  void order_for_ranks(const Eigen::SparseMatrix<double>& A);
  Eigen::SparseMatrix<double> ordered_pressure_mass() const;

  std::string name_;
  LinearSolverOptions options_;
  bool iterative_;
  const PetscPlugin* plugin_ = nullptr;
  int ranks_ = 1;
  void* solver_ = nullptr;
  std::vector<char> is_pressure_, is_pressure_ordered_;
  std::vector<int> locality_;  // set_locality_order's, or empty
  // Old number → the plugin's (identity on one rank; order_for_ranks).
  Eigen::PermutationMatrix<Eigen::Dynamic> order_;
  bool symmetric_ = false;
  Eigen::SparseMatrix<double> pressure_mass_;
  Eigen::VectorXd last_;  // the last solution, in order_: the next solve's first iterate
};

}  // namespace fsi
