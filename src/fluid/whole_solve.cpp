#include "common/errors.hpp"
#include "common/timer.hpp"
#include "fluid/stokes_strategy.hpp"

namespace fsi {

WholeSolve::WholeSolve(StokesAssembler& assembler, const std::string& solver, FluidTiming& timing, FluidSolution& out,
                       const LinearSolverOptions& options)
    : assembler_(assembler), solver_(make_sparse_solver(solver, options)), timing_(timing), out_(out) {}

// Before the first assembly: the solver told what the unknowns are and, if it
// distributes the rows over MPI ranks, given an order that keeps neighbours together;
// the assembler then assembles only this rank's rows.
void WholeSolve::prepare() {
  if (prepared_) return;
  solver_->describe_system(assembler_.pressure_unknowns(), assembler_.symmetric());
  if (solver_->wants_locality_order()) {  // refused (too few unknowns a rank): not prepared
    solver_->set_locality_order(assembler_.curve_rank());
    assembler_.share_rows(solver_->rows_here());
  }
  prepared_ = true;
}

// Assembles K (incrementally), factorises all of it (one symbolic analysis for the
// run: the pattern never changes), solves.
void WholeSolve::solve(const Eigen::VectorXd& chi, double eps, SampledTriangles) {
  prepare();
  {
    const Stopwatch clock;
    assembler_.assemble(chi, eps);
    timing_.assembly += clock.elapsed();
  }
  const Eigen::SparseMatrix<double>& K = assembler_.matrix();
  const Eigen::VectorXd& rhs = assembler_.rhs();
  {
    const Stopwatch clock;
    if (!analysed_) {
      solver_->analyze(K);
      analysed_ = true;
      timing_.analysis += clock.elapsed();
      ++timing_.analyses;
    }
    solver_->release();  // the last set-up freed before the pressure mass matrix is built
    if (solver_->wants_pressure_mass()) {
      const Eigen::VectorXd weight = (1.0 - chi.array()) / assembler_.mu();  // the fluid's part: χ = 0
      solver_->set_pressure_mass(assembler_.pressure_mass(weight));
    }
    solver_->factorize(K);
    timing_.factorization += clock.elapsed();
    ++timing_.factorizations;
  }
  const Stopwatch clock;
  const Eigen::VectorXd x = solve_counting_iterations(*solver_, rhs, timing_.linear_iterations);
  if (!x.allFinite()) throw SolverFailure("the Stokes solve produced a non-finite value");
  // A nearly singular matrix can factorise without a zero pivot and give garbage:
  // one product with K (~1% of a factorisation) catches it. The direct solvers reach
  // ~1e-14 here, up to ε = 1e-7 (docs/performance.md); 1e-8 leaves a wide margin.
  const double residual = norm(K * x - rhs), scale = norm(rhs);
  if (!(residual <= solver_->residual_tolerance() * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned for " + solver_->name() +
                        ": relative residual " + std::to_string(residual / scale) + " after the solve (" +
                        (solver_->last_iterations() >= 0 ? "iterative" : "direct") + ")");
  assembler_.fields(x, chi, eps, out_);
  timing_.solve += clock.elapsed();
}

}  // namespace fsi
