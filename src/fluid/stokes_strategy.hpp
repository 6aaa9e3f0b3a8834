// How the penalised Stokes system K(χ, ε) x = b of a StokesAssembler is solved
// (PenalisedStokes chooses one, fluid.factorization):
// - WholeSolve: K assembled (updated where χ changed) and refactorised whole;
// - SubstructuredSolve: the far field, where χ = 0, factorised once per near region
//   and condensed onto it (RegionSchurSolver); per χ only the near region is
//   factorised, and the far field's values are expanded only when asked for.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "fluid/region_schur.hpp"
#include "fluid/sparse_solver.hpp"
#include "fluid/stokes_assembler.hpp"

namespace fsi {

struct FluidTiming {
  double assembly = 0, factorization = 0, solve = 0;
  double analysis = 0;  // the one symbolic analysis, part of `factorization`
  int analyses = 0, factorizations = 0, reused = 0;  // reused: χ unchanged, previous solution returned
  // Substructured solves (RegionSchurSolver): the far-field factorisations (one per
  // near region, part of `factorization`) and the expansions (part of `solve`).
  double far_factorization = 0, expansion = 0;
  int regions = 0;
  int far_refactorizations = 0;  // expansions that refactorised a released far field
  // An iterative linear solver's iterations, per solve (empty: a direct solver).
  std::vector<int> linear_iterations;
};

// Where a substructured solve stands (see StokesSolveStrategy::near_region_state).
struct NearRegionState {
  std::vector<char> mask;  // the near triangles (empty: none)
  double margin = 0;       // the region's margin around χ's support
};

// The triangles where a solution's fields will be read (null: everywhere).
using SampledTriangles = const std::vector<int>*;

class StokesSolveStrategy {
 public:
  virtual ~StokesSolveStrategy() = default;
  // Each strategy writes one solution, its owner's (given to its constructor).
  // The solution for χ and ε, exact at least on `sampled`. Throws SolverFailure (a
  // failed or too inaccurate factorisation) with the last solution kept, exact
  // everywhere it was but where SubstructuredSolve::build_near_region says.
  virtual void solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) = 0;
  // The last solution made exact on `sampled` too.
  virtual void extend(SampledTriangles /*sampled*/) {}
  // Before ε changes: what the last solution still needs of the factorisations it
  // came from.
  virtual void settle() {}
  // Where χ is expected to go (per triangle; empty: nowhere known), e.g. the
  // structure under its applied loads alone.
  virtual void expect(Eigen::VectorXd /*chi_hint*/) {}
  // A new run (what it keeps for the next one: see the strategy).
  virtual void new_run() {}
  // The assembler's loads or terms changed (after settle()): what was condensed from
  // them is stale.
  virtual void load_changed() {}
  // The added terms changed on triangles where χ > 0 only, and add nothing where χ = 0,
  // before or after (the penalty's velocity between a coupled step's passes): the last
  // solution is not needed beyond where it is exact. By default as any change.
  virtual void near_changed() {
    settle();
    load_changed();
  }
  // The substructured solve's near region, for a checkpoint: a resumed run factorises
  // the same region, so that its numbers are the uninterrupted run's to the bit (empty
  // mask: no region to restore).
  virtual NearRegionState near_region_state() const { return {}; }
  virtual void restore_near_region(NearRegionState /*state*/) {}
  // The new run starts from the last run's state (a warm start): what the last run
  // ended with may serve its first solve (see the strategy).
  virtual void continue_last_run() {}
  // A resumed time run (SPEC §12 checkpoints): `last` is the solution the interrupted
  // run's last solve ended with, which its next solve would have started from
  // (Newton's iterate), so that the resumed run takes the same steps to the same bits.
  virtual void start_from(const FluidSolution& /*last*/) {}
  // A time step's convecting velocity (semi-implicit convection: NewtonOptions).
  virtual void linearise_about(FluidSolution /*w*/) {}
  virtual std::string name() const = 0;
  // Whether it factors symmetric systems only (PenalisedStokes::solve refuses an
  // unsymmetric K then, naming it).
  virtual bool needs_symmetry() const = 0;
  virtual const RegionSchurSolver* region() const { return nullptr; }
};

class WholeSolve final : public StokesSolveStrategy {
 public:
  WholeSolve(StokesAssembler& assembler, const std::string& solver, FluidTiming& timing, FluidSolution& out,
             const LinearSolverOptions& options = {});
  void solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) override;
  std::string name() const override { return solver_->name(); }
  bool needs_symmetry() const override { return solver_->needs_symmetry(); }
  void new_run() override { assembler_.forget_assembly(); }
  // ‖v‖ of a vector over the assembler's rows (on several ranks each holds some: the
  // norm over all of them, the same on every rank).
  double norm(const Eigen::VectorXd& v) const { return solver_->norm_over_ranks(v); }
  // What the first solve does before its assembly (whole_solve.cpp), for a caller that
  // assembles before it (NewtonSolve's residual).
  void prepare();

 private:
  StokesAssembler& assembler_;
  std::unique_ptr<SparseDirectSolver> solver_;
  FluidTiming& timing_;
  FluidSolution& out_;
  bool prepared_ = false, analysed_ = false;
};

class SubstructuredSolve final : public StokesSolveStrategy {
 public:
  // Far fields whose factorisation needs more than far_factor_budget_mb (MUMPS's
  // estimate) are not kept: each expansion refactorises them. INFINITY: keep all.
  SubstructuredSolve(StokesAssembler& assembler, const std::string& solver, FluidTiming& timing, FluidSolution& out,
                     double far_factor_budget_mb);
  void solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) override;
  void extend(SampledTriangles sampled) override;
  void settle() override;
  // The first near region also covers the hint, so that a structure moving there
  // does not force a second far-field factorisation.
  void expect(Eigen::VectorXd chi_hint) override;
  // The near region and its far-field factorisation are kept (χ = 0 there, so they
  // hold for any ε): a sweep's next row reuses them if its first region is the same.
  void new_run() override;
  // The run's first region is the last run's if it covers the first χ (however it
  // rounds: a warm start is not a run of its own), its far field not refactorised.
  void continue_last_run() override { continue_region_ = true; }
  // The far field's condensed load is the old one: the next solve condenses the new
  // one, or builds the region again if the far field's operator changed.
  void load_changed() override;
  // The last solution stays exact on its near region only (no expansion).
  void near_changed() override;
  NearRegionState near_region_state() const override;
  void restore_near_region(NearRegionState state) override;
  std::string name() const override { return whole_.name() + "+schur"; }
  // MUMPS's Schur complement (SYM = 2) and the far field's self-adjoint products.
  bool needs_symmetry() const override { return true; }
  const RegionSchurSolver* region() const override { return region_.get(); }

 private:
  void solve_near(const Eigen::VectorXd& chi, double eps);
  void expand();
  bool exact_on(SampledTriangles sampled) const;
  bool near_region_covers(const Eigen::VectorXd& chi) const;
  void start_region(const Eigen::VectorXd& chi, double eps);
  std::vector<char> region_mask(const Eigen::VectorXd& chi);
  void build_near_region(const Eigen::VectorXd& chi, double eps, std::vector<char> near);
  void refresh_far_load(const Eigen::VectorXd& chi, double eps);

  StokesAssembler& assembler_;
  WholeSolve whole_;  // when the near region would be most of D, or χ = 0
  FluidTiming& timing_;
  FluidSolution& out_;
  double far_factor_budget_mb_;
  std::unique_ptr<RegionSchurSolver> region_;
  // Where the last solution is exact when its region was replaced before it was
  // completed (that region's far factors released: completing it would have cost a
  // far-field factorisation, and only a failed solve right after would need it).
  std::vector<char> stale_mask_;
  Eigen::VectorXd hint_;                      // see expect()
  double margin_ = 0;                         // the near region: χ's support's box grown by this
  std::vector<char> interior_vertex_;         // vertices whose triangles are all near
  bool too_large_ = false;                    // the near region would be most of D: solve whole
  bool first_of_run_ = true;                  // the next solve is a run's first
  bool continue_region_ = false;              // see continue_last_run()
  bool far_load_stale_ = false;               // see load_changed()
  std::vector<char> restored_mask_;           // see restore_near_region()
  // The last solution is exact on the near region only; its χ and ε, for the
  // expansion (and the bubbles it recovers).
  bool pending_expansion_ = false;
  Eigen::VectorXd pending_chi_;
  double pending_eps_ = 0;
};

}  // namespace fsi
