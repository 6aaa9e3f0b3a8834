// Steady Stokes on the fixed mesh of D with the structure as a penalty (paper §4,
// eqs. 25–26, SPEC §3):
//     ∫ 2μ ε(v):ε(w) − ∫ (div w) p + (1/ε) ∫ χ v·w = ∫ f·w (+ ∫_{Γ_N} h·w),
//     −∫ (div v) q = 0,
// mini element with condensed bubbles. The velocity is prescribed on the Dirichlet
// labels; the rest of the boundary is natural (traction h, zero by default). There
// is no mean-pressure constraint: with a traction boundary the pressure is unique.
//
// The façade of three parts: the discrete problem (StokesAssembler), how it is
// solved (a StokesSolveStrategy: whole, or substructured around the structure), and
// the state a fixed-point loop sees: χ and ε in, the last solution out, reused while
// χ does not change.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <memory>
#include <string>

#include "fluid/newton_solve.hpp"
#include "fluid/sparse_solver.hpp"
#include "fluid/stokes_assembler.hpp"
#include "fluid/stokes_strategy.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// How solve() factorises: `schur` keeps the far field's factorisation and its Schur
// complement for the whole run and refactorises only the region χ can reach
// (SubstructuredSolve); `whole` refactorises all of K after every χ change.
enum class FluidFactorization { schur, whole };

class PenalisedStokes {
 public:
  // `factorization` and its budget as set_factorization(factorization, budget) right
  // after, but a `schur` one starts ordering the unknowns (on the second core) before
  // the set-up.
  PenalisedStokes(const Mesh& mesh, double mu, double eps, const VectorField& f,
                  const FluidBoundaryConditions& bc,
                  const std::string& solver = kDefaultSparseSolver,
                  FluidFactorization factorization = FluidFactorization::whole,
                  double far_factor_budget_mb = INFINITY);
  // The strategy refers to the assembler, the timing and the solution held here.
  PenalisedStokes(const PenalisedStokes&) = delete;
  PenalisedStokes& operator=(const PenalisedStokes&) = delete;

  // Before the first solve. far_factor_budget_mb (schur): far fields whose
  // factorisation needs more (MB, MUMPS's estimate) are not kept between expansions.
  void set_factorization(FluidFactorization f, double far_factor_budget_mb = INFINITY);
  FluidFactorization factorization() const { return factorization_; }

  // χ per triangle (0 outside the structure, 1 inside; fractions allowed).
  void set_chi(const Eigen::VectorXd& chi);
  const Eigen::VectorXd& chi() const { return chi_; }
  // A new penalty ε (the pattern and its symbolic analysis are kept).
  void set_eps(double eps);
  // A new body force f_F (the same χ may follow: the next solve solves again).
  void set_body_force(const VectorField& f);
  // New boundary data on the same labels (StokesAssembler::set_boundary_data).
  void set_boundary_data(const FluidBoundaryConditions& bc);
  // The viscous term's form (SPEC §10 fluid.viscous_form): a new version.
  void set_viscous_form(ViscousForm form);
  ViscousForm viscous_form() const { return assembler_.viscous_form(); }
  // Steady Navier–Stokes (SPEC §10): the convection ρ(v·∇)v added and every solve
  // Newton's iteration (NewtonSolve), on the whole factorisation with this object's
  // solver, which must factor unsymmetric matrices. Before the first solve; the
  // `schur` factorisation is refused (std::invalid_argument).
  void set_navier_stokes(const NewtonOptions& options);
  // The linear solver by name (make_sparse_solver: e.g. "petsc-iterative", SPEC §13)
  // and its controls, on the whole factorisation. Before the first solve and before
  // set_navier_stokes (std::logic_error otherwise).
  void set_linear_solver(const std::string& solver, const LinearSolverOptions& options);
  const LinearSolverOptions& linear_options() const { return linear_options_; }
  // Newton's report (null for Stokes).
  const FluidNewtonReport* newton() const { return newton_ ? &newton_->report() : nullptr; }
  // A further term of the operator (mini_element.hpp ElementTerm: convection for
  // Navier–Stokes); a new version. An unsymmetric term needs a solver path that
  // factors unsymmetric systems (`whole` with "umfpack", "umfpack-metis" or "eigen-lu"):
  // solve() refuses the others with a SolverFailure naming them.
  void add_term(std::shared_ptr<const ElementTerm> term);
  // The added terms' data changed (Newton's new velocity to linearise about): a new
  // version, every triangle assembled again.
  void terms_changed();
  // The same where the change is confined to triangles with χ > 0, the added terms
  // adding nothing where χ = 0 before and after (a coupled pass's penalty velocity):
  // the substructured solve keeps its far field, and the last solution is then exact
  // only where it was (its near region).
  void near_terms_changed();
  // The substructured solve's near region (a checkpoint's), and a resumed run's.
  NearRegionState near_region_state() const { return strategy_->near_region_state(); }
  void restore_near_region(NearRegionState state) { strategy_->restore_near_region(std::move(state)); }
  bool symmetric() const { return assembler_.symmetric(); }
  // Where χ is expected to go (per triangle, as χ; empty: nowhere known), e.g. the
  // structure under its applied loads alone: the substructured solve's first near
  // region covers it too.
  void expect_chi(Eigen::VectorXd chi_hint) { strategy_->expect(std::move(chi_hint)); }
  // A new run: forget the last solution (the next solve() refactorises). What the
  // strategy keeps for the next run: see SubstructuredSolve::new_run.
  void reset();
  // After reset(), for a run that starts from the last run's state (a study's warm
  // start, at another ε): the substructured solve keeps the last near region and its
  // far-field factorisation (χ = 0 there: they hold for any ε) if it covers the first χ.
  void continue_last_run() { strategy_->continue_last_run(); }
  // A resumed time run: the next solve starts where the interrupted run's would have
  // (StokesSolveStrategy::start_from: Newton's iterate, `last`).
  void start_from(const FluidSolution& last) { strategy_->start_from(last); }
  // Semi-implicit convection (NewtonOptions::semi_implicit): each solve is one Oseen
  // solve about the step's convecting velocity, given by linearise_about().
  bool semi_implicit() const { return newton_ && newton_->options().semi_implicit; }
  void linearise_about(FluidSolution w) { strategy_->linearise_about(std::move(w)); }

  // Solves for the current problem; if nothing of it (χ, ε, the load) changed since
  // the last solve, returns the previous solution without refactorising. The fields
  // are exact at least on the triangles `sampled` (null: everywhere); the
  // substructured solve may leave the rest for later (FluidSolution::exact_on).
  // Throws SolverFailure.
  const FluidSolution& solve(SampledTriangles sampled = nullptr);
  // The last successful solution (after a failed solve: the one before), made exact
  // on `sampled` (null: everywhere). Throws SolverFailure if that needs a solve that
  // fails, or cannot be done (the solve after a change of near region failed).
  const FluidSolution& solution(SampledTriangles sampled = nullptr);
  bool has_solution() const { return solved_once_; }
  const Eigen::VectorXd& last_solution_chi() const { return solved_chi_; }  // its χ

  const Mesh& mesh() const { return assembler_.mesh(); }
  double mu() const { return assembler_.mu(); }
  double eps() const { return eps_; }
  int unknowns() const { return assembler_.unknowns(); }
  long nonzeros() const { return assembler_.nonzeros(); }  // of the whole K
  const FluidTiming& timing() const { return timing_; }
  std::string solver_name() const { return strategy_->name(); }
  // The substructured solver in use (null before the first substructured solve).
  const RegionSchurSolver* region() const { return strategy_->region(); }
  // K and rhs for the current χ over all triangles, without factorising (for
  // benchmarks and tests), and the system as last assembled.
  void assemble_full() { assembler_.assemble_full(chi_, eps_); }
  const Eigen::SparseMatrix<double>& matrix() const { return assembler_.matrix(); }
  const Eigen::VectorXd& rhs() const { return assembler_.rhs(); }

 private:
  template <class Change>
  void change_problem(Change&& change);

  StokesAssembler assembler_;
  std::string solver_;
  LinearSolverOptions linear_options_;
  FluidFactorization factorization_ = FluidFactorization::whole;
  std::unique_ptr<StokesSolveStrategy> strategy_;
  const NewtonSolve* newton_ = nullptr;  // the strategy, for Navier–Stokes
  Eigen::VectorXd chi_;
  double eps_;
  // The problem's version: any change of χ, ε or the load makes a new one; a solution
  // is reused only for the version it was solved for.
  long version_ = 0, solved_version_ = -1;
  bool solved_once_ = false;
  Eigen::VectorXd solved_chi_;
  FluidSolution solution_;
  FluidTiming timing_;
};

}  // namespace fsi
