// fluid.linear_solver = "petsc-mumps" | "petsc-iterative" (SPEC §13): the fluid's
// linear systems through PETSc, behind the same interface as the direct solvers
// (sparse_solver.hpp), PETSc itself in a plugin loaded on first use
// (petsc_plugin.hpp). An iterative "factorisation" is the preconditioner's set-up;
// each solve starts from the last solution (a warm start) and records its iterations.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <limits>
#include <memory>
#include <string>
#include <utility>
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
  // The unknowns sorted by `rank`: PETSc's blocks of rows then parts of the domain.
  void set_locality_order(std::vector<int> rank) override;
  std::vector<char> rows_here() const override;
  void set_pressure_mass(Eigen::SparseMatrix<double> M) override { pressure_mass_ = std::move(M); }
  double norm_over_ranks(const Eigen::VectorXd& v) const override;
  bool on_every_rank(bool ok) const override;
  double residual_tolerance() const override;
  // The iterative solver holds K's blocks after factorize() (petsc_block_operator.hpp):
  // the caller may free K before finish_factorization().
  bool detaches_from_operator() const override { return iterative_; }
  double last_residual() const override { return last_residual_; }

 protected:
  // On several ranks, the unknowns renumbered first (order_).
  void analyze_pattern(const Eigen::SparseMatrix<double>& A) override;
  void factorize_values(const Eigen::SparseMatrix<double>& A) override;
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) override;
  void release_factorization() override;
  void finish_factorization_values() override;

 public:
  std::pair<int, int> share(int count) const override;
  void sum_shares(double* values, Eigen::Index count) const override;

 private:
  void require_enough_unknowns(Eigen::Index n) const;
  void set_order(const std::vector<int>& pivots);
  std::vector<std::pair<int, int>> row_blocks(int n) const;
  void order_for_ranks(const Eigen::SparseMatrix<double>& A);
  double sum_over_ranks(double value) const;
  std::vector<int> pressure_order(const std::vector<char>& is_pressure_ordered) const;

  std::string name_;
  LinearSolverOptions options_;
  bool iterative_;
  const PetscPlugin* plugin_ = nullptr;
  int ranks_ = 1;
  void* solver_ = nullptr;
  std::vector<char> is_pressure_;
  std::vector<int> pressure_order_;  // pressure_order's, fixed at the analysis
  // Old number → the plugin's (identity on one rank; set_order), and this rank's rows
  // in the plugin's numbering, [first_, last_), and of the pressure's, [p_first_, p_last_).
  Eigen::PermutationMatrix<Eigen::Dynamic> order_;
  int first_ = 0, last_ = 0, p_first_ = 0, p_last_ = 0;
  bool symmetric_ = false;
  Eigen::SparseMatrix<double> pressure_mass_;
  Eigen::VectorXd last_solution_;  // in order_: the next solve's first iterate
  double last_residual_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace fsi
