// Sparse direct solvers for the condensed Stokes system, behind one interface so
// they can be measured against each other (docs/performance.md). The pattern is
// analysed once (ordering, elimination tree); when χ changes only the values do,
// and only the numeric factorisation is redone.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fsi {

// SolverFailure "<who>: the matrix has a non-finite entry ..." unless every stored
// entry of A is finite (the vector form: the right-hand side). MUMPS, UMFPACK and
// CHOLMOD do not define what they do with NaN or ±inf: refused before each numeric
// factorisation and each solve.
void require_finite_matrix(const Eigen::SparseMatrix<double>& A, const std::string& who);
void require_finite_rhs(const Eigen::VectorXd& b, const std::string& who);
// The same, the check's outcome given (on several ranks: every rank's, on_every_rank).
void require_finite_matrix(bool finite, const std::string& who);
void require_finite_rhs(bool finite, const std::string& who);

// What the last factorisation cost, as the library reports it (−1: not reported).
// Flop counts follow each library's own convention; compare them within one.
struct FactorStatistics {
  double entries = -1;  // stored entries of the factors (L, or L and U)
  double flops = -1;
};

// An iterative solver's controls (fluid.linear_tol, fluid.linear_max_iterations,
// fluid.krylov).
struct LinearSolverOptions {
  LinearSolverOptions() = default;
  LinearSolverOptions(double tol_, int max_iterations_, std::string krylov_ = "gmres")
      : tol(tol_), max_iterations(max_iterations_), krylov(std::move(krylov_)) {}
  double tol = 1e-10;  // ‖b − A x‖ ≤ tol ‖b‖
  int max_iterations = 1000;
  std::string krylov = "gmres";  // "gmres" | "bicgstab" (PetscSolverConfig::krylov)
  // The iterative solver's Schur preconditioner: S_p = D − B diag(A)⁻¹ Bᵀ alone
  // ("selfp"), or minus the fluid's pressure mass matrix too (petsc_plugin.cpp).
  bool schur_mass = true;
  // On several MPI ranks, fewer unknowns a rank than this are refused (PetscSolver).
  int min_unknowns_per_rank = 2000;
};

class SparseDirectSolver {
 public:
  virtual ~SparseDirectSolver() = default;
  // Symbolic analysis of the pattern of the symmetric matrix A (both triangles
  // stored, compressed); done once.
  void analyze(const Eigen::SparseMatrix<double>& A);
  // Numeric factorisation of A, whose pattern must be the analysed one (checked:
  // std::logic_error otherwise). A singular matrix or a non-finite entry throws
  // SolverFailure.
  void factorize(const Eigen::SparseMatrix<double>& A);
  // x with A x = rhs for the last factorised A (SolverFailure if rhs is not finite).
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);
  // Before the next pass's matrices are built: frees what the last factorisation holds
  // and the next rebuilds anyway (PETSc's iterative set-up: petsc_solver.hpp), so that
  // the two never live together; solve() then needs a factorize() first.
  void release();
  // Whether factorize() leaves the solver holding what it needs of A (petsc-iterative:
  // A's blocks, petsc_block_operator.hpp), so that the caller may free A before
  // finish_factorization(), the rest of the set-up and the memory's peak; the solve's
  // accuracy is then last_residual(), computed with those blocks. The others read A
  // until the solve (UMFPACK's refinement too), and the caller computes the residual.
  virtual bool detaches_from_operator() const { return false; }
  // After factorize(), within the factorisation's time: the rest of the set-up of a
  // solver that detaches_from_operator() (the next solve() does it if not called).
  void finish_factorization();
  // ‖rhs − A x‖ / ‖rhs‖ of the last solve() of a solver that detaches_from_operator(),
  // computed anew with the operator it holds; NaN for the others.
  virtual double last_residual() const { return std::numeric_limits<double>::quiet_NaN(); }
  virtual std::string name() const = 0;
  virtual FactorStatistics statistics() const { return {}; }
  // Whether it factors symmetric matrices only (it reads one triangle, or pivots
  // symmetrically: LDLᵀ); an unsymmetric K (convection) needs a solver that does not.
  virtual bool needs_symmetry() const = 0;
  // Before analyze(): per unknown, 1 for a pressure's (a block preconditioner's
  // split), and whether the values will stay symmetric (petsc_solver.hpp); the other
  // solvers do not need either.
  virtual void describe_system(std::vector<char> /*is_pressure*/, bool /*symmetric*/) {}
  // Whether it preconditions with a pressure mass matrix, which the caller then gives
  // (set_pressure_mass, before each factorize: Σ_T w_T ∫_T p q on the pressure
  // unknowns, w = (1 − χ)/μ; StokesAssembler::pressure_mass).
  virtual bool wants_pressure_mass() const { return false; }
  // Whether it distributes the unknowns over MPI ranks in blocks, which the caller
  // then gives an order that keeps neighbours together (set_locality_order, before
  // analyze(): rank[k] sorts unknown k; StokesAssembler::dof_rank, METIS on the vertex
  // graph); without it the solver orders the matrix's own graph, 9 times larger.
  virtual bool wants_locality_order() const { return false; }
  virtual void set_locality_order(std::vector<int> /*rank*/) {}
  // After set_locality_order: per unknown, 1 for the rows this rank holds (empty: all).
  // The caller then gives analyze(), factorize(), solve() and set_pressure_mass() only
  // those rows of its matrices and right-hand sides, the others empty or zero
  // (StokesAssembler::share_rows), and gets the whole solution back on every rank.
  virtual std::vector<char> rows_here() const { return {}; }
  virtual void set_pressure_mass(Eigen::SparseMatrix<double> /*M*/) {}
  // ‖v‖ of a vector of which each rank holds its rows_here() (the others zero): the
  // squares summed over the ranks, so that every rank takes the same decisions.
  virtual double norm_over_ranks(const Eigen::VectorXd& v) const { return v.norm(); }
  // Whether `ok` holds on every rank: a failure on one rank's rows is every rank's,
  // before a collective solve that the others would otherwise wait in for ever.
  virtual bool on_every_rank(bool ok) const { return ok; }
  // Work split over the ranks: this rank's even share [first, last) of `count` items
  // (all of them on one rank); and `count` values of which each rank computed its
  // share, the others zero, summed over the ranks entry by entry in place, so that
  // every rank holds them all (a sum with zeros: the values unchanged to the bit).
  virtual std::pair<int, int> share(int count) const { return {0, count}; }
  virtual void sum_shares(double* /*values*/, Eigen::Index /*count*/) const {}
  // The last solve's iterations (an iterative solver's, also when it failed; −1 for a
  // direct solver, or a solve refused before it began).
  int last_iterations() const { return last_iterations_; }
  // The relative residual ‖A x − b‖/‖b‖ a solve must reach for its caller to accept
  // it (the callers check it: a nearly singular matrix can factorise and give garbage).
  virtual double residual_tolerance() const { return 1e-8; }

  int analyses() const { return analyses_; }
  int factorizations() const { return factorizations_; }

 protected:
  virtual void analyze_pattern(const Eigen::SparseMatrix<double>& A) = 0;
  virtual void factorize_values(const Eigen::SparseMatrix<double>& A) = 0;
  virtual Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) = 0;
  virtual void release_factorization() {}
  virtual void finish_factorization_values() {}

 protected:
  int last_iterations_ = -1;  // set by an iterative solve_factorized

 private:
  // The analysed pattern, kept as its size and a fingerprint: a copy of its indices
  // would be 4 bytes a nonzero (19 MB at 223 256 unknowns, issue 32's memory budget).
  struct Pattern {
    Eigen::Index n = -1, nonzeros = -1;
    std::uint64_t fingerprint = 0;
    bool operator==(const Pattern&) const = default;
  };
  static Pattern pattern_of(const Eigen::SparseMatrix<double>& A);
  Pattern analysed_;
  int analyses_ = 0, factorizations_ = 0;
  bool factorized_ = false;
};

// Names accepted by make_sparse_solver, the default first. Measured against each
// other in bench/fluid_bench.cpp; docs/performance.md says why the default is it.
const std::vector<std::string>& sparse_solver_names();
inline const char* const kDefaultSparseSolver = "mumps-metis";

// "mumps-metis", "mumps-pord", "mumps-amd": MUMPS, symmetric indefinite (LDLᵀ with
// 1×1/2×2 pivoting), ordering as named (METIS through CHOLMOD). "umfpack": UMFPACK
// LU, default controls (the former default, the calls Eigen's UmfPackLU makes).
// "umfpack-metis": its symmetric strategy, METIS, no iterative refinement.
// "cholmod-ldlt": CHOLMOD simplicial LDLᵀ (METIS); "eigen-ldlt": Eigen's
// SimplicialLDLT (AMD); "eigen-lu": Eigen's SparseLU (COLAMD). The LDLᵀ without
// pivoting rely on the system being nearly quasi-definite. Symmetric only (needs_symmetry):
// the MUMPS, CHOLMOD and Eigen LDLᵀ ones; "umfpack", "umfpack-metis" (LU, its
// symmetric strategy an ordering choice), "eigen-lu" and "mumps-lu" (MUMPS unsymmetric,
// SYM = 0, METIS on the symmetric pattern) factor any matrix.
// x = solver.solve(rhs), the solve's iterations (an iterative solver's) appended to
// `iterations`, also when it throws (summary.json's fluid.linear_iterations).
Eigen::VectorXd solve_counting_iterations(SparseDirectSolver& solver, const Eigen::VectorXd& rhs,
                                          std::vector<int>& iterations);

// "petsc-mumps", "petsc-iterative": through PETSc (petsc_solver.hpp), with `options`.
std::unique_ptr<SparseDirectSolver> make_sparse_solver(const std::string& name,
                                                       const LinearSolverOptions& options = {});

// MUMPS as "mumps-metis" but with the elimination order given (order[k] = the k-th
// pivot; a permutation of the unknowns), e.g. to keep a dense block last.
std::unique_ptr<SparseDirectSolver> make_mumps_solver(std::vector<int> order);

// METIS nested dissection of the pattern of the symmetric A (both triangles stored,
// compressed), through CHOLMOD, which links METIS on Debian (MUMPS's Debian build
// does not). perm[k] = the k-th pivot.
std::vector<int> metis_ordering(const Eigen::SparseMatrix<double>& A);

}  // namespace fsi
