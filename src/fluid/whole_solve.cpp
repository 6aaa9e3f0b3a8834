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
  // A solver that frees K is chosen for memory: the element loads computed when needed.
  if (solver_->detaches_from_operator()) assembler_.keep_element_loads(false);
  solver_->describe_system(assembler_.pressure_unknowns(), assembler_.symmetric());
  if (solver_->wants_locality_order()) {  // refused (too few unknowns a rank): not prepared
    solver_->set_locality_order(assembler_.curve_rank());
    assembler_.share_rows(solver_->rows_here());
  }
  prepared_ = true;
}

// Assembles K (incrementally; all of it for a solver that frees K), factorises all of
// it (one symbolic analysis for the run: the pattern never changes), solves.
void WholeSolve::solve(const Eigen::VectorXd& chi, double eps, SampledTriangles) {
  prepare();
  // The last set-up freed before this pass's matrices are built (K too, for a solver
  // that freed it: detaches_from_operator); the factorisation rebuilds it anyway.
  solver_->release();
  {
    const Stopwatch clock;
    assembler_.assemble(chi, eps);
    if (solver_->detaches_from_operator()) assembler_.release_offsets();  // K is built anew each pass
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
    if (solver_->wants_pressure_mass()) {
      const Eigen::VectorXd weight = (1.0 - chi.array()) / assembler_.mu();  // the fluid's part: χ = 0
      solver_->set_pressure_mass(assembler_.pressure_mass(weight));
    }
    solver_->factorize(K);
    // K freed before the rest of the set-up, the memory's peak, by a solver that holds
    // its own blocks of it (petsc-iterative; docs/performance.md, "K freed before the
    // set-up").
    if (solver_->detaches_from_operator()) assembler_.release_matrix();
    solver_->finish_factorization();
    timing_.factorization += clock.elapsed();
    ++timing_.factorizations;
  }
  const Stopwatch clock;
  const Eigen::VectorXd x = solve_counting_iterations(*solver_, rhs, timing_.linear_iterations);
  if (!x.allFinite()) throw SolverFailure("the Stokes solve produced a non-finite value");
  // A nearly singular matrix can factorise without a zero pivot and give garbage:
  // one product with K (~1% of a factorisation) catches it; a solver that freed K
  // computed it with its own blocks. The direct solvers reach ~1e-14 here, up to
  // ε = 1e-7 (docs/performance.md); 1e-8 leaves a wide margin.
  const double scale = norm(rhs);
  const double residual =
      solver_->detaches_from_operator() ? solver_->last_residual() * scale : norm(K * x - rhs);
  if (!(residual <= solver_->residual_tolerance() * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned for " + solver_->name() +
                        ": relative residual " + std::to_string(residual / scale) + " after the solve (" +
                        (solver_->last_iterations() >= 0 ? "iterative" : "direct") + ")");
  // The set-up of a solver that freed K is rebuilt at each pass: freed now, not at the
  // next pass, so that what follows the solve (the fields, the structure, the outputs)
  // does not peak above it.
  if (solver_->detaches_from_operator()) solver_->release();
  // The bubbles, element by element, split over the ranks (0.25 s at 930 681
  // triangles, on every rank for all of them before; docs/performance.md, "The
  // bubbles shared, and the fields as views").
  const auto [first, last] = solver_->share(assembler_.mesh().num_triangles());
  assembler_.fields(x, chi, eps, out_, first, last);
  solver_->sum_shares(out_.bubble.data(), out_.bubble.size());
  timing_.solve += clock.elapsed();
}

}  // namespace fsi
