// The steady Navier–Stokes problem (SPEC §10) as a way of solving the penalised
// system: Newton's method on the mini element's condensed equations, each step the
// Jacobian at the last iterate w,
//     K(w) v = F + ρ∫(w·∇)w·φ,   K(w) = Stokes + (1/ε)χ + ρ∫[(w·∇)δ + (δ·∇)w]·φ
// (NewtonConvection, the bubbles kept), assembled and factorised whole by a
// WholeSolve: the symbolic analysis is done once and serves every step and every
// fixed-point pass. The first solve starts from v = 0, so its first step is the
// Stokes solution; later solves (a new χ in the next pass) start from the last
// solution, and take a step or two.
//
// Convergence: the relative residual ‖K(w)x_w − b(w)‖ / max(‖b(0)‖, ‖b(w)‖) of the
// condensed equations (which equals the Schur-reduced full residual: zero exactly at
// the discrete solution), against `tol`. A Newton step is damped (halved) until the
// residual falls; one that does not help even at a sixteenth is taken back and
// replaced by a Picard (Oseen) step; `max_steps` bounds both, and its excess is a
// SolverFailure with the residual history (a steady flow may not exist at that
// Reynolds number).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fluid/convection.hpp"
#include "fluid/stokes_strategy.hpp"

namespace fsi {

// The sparse solver of Navier–Stokes's Jacobians (make_sparse_solver's name):
// measured against the others in bench/fluid_bench.cpp, docs/performance.md.
inline const char* const kNavierStokesSolver = "mumps-lu";

struct NewtonOptions {
  double rho = 1;          // ρ_F
  double tol = 1e-10;      // relative residual to reach (fluid.newton_tol)
  int max_steps = 30;      // Newton's and Picard's steps per solve (fluid.newton_max_steps)
  // A time step's convection semi-implicit (time.convection): each solve is one Oseen
  // (Picard) solve about the velocity given by linearise_about(), not Newton's iteration.
  bool semi_implicit = false;
};

// What the Newton iterations did: the last solve's residual history and the run's totals.
struct FluidNewtonReport {
  std::vector<double> residuals;  // the last solve's relative residuals, its start first
  // The last solve's steps: Newton's (damped: of them, shortened), Picard's, and the
  // Newton steps taken back (no damping helped) for a Picard step.
  int steps = 0, damped = 0, picard_steps = 0, rejected = 0;
  int total_steps = 0, total_picard_steps = 0, solves = 0;  // over the run
  double max_final_residual = 0;  // over the run's solves
};

class NewtonSolve final : public StokesSolveStrategy {
 public:
  // Adds the convection term to `assembler` (before any solve). `solver` must factor
  // unsymmetric matrices (PenalisedStokes::solve refuses the others).
  NewtonSolve(StokesAssembler& assembler, const std::string& solver, FluidTiming& timing, FluidSolution& out,
              const NewtonOptions& options, const LinearSolverOptions& linear = {});
  void solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) override;
  std::string name() const override { return whole_.name(); }
  bool needs_symmetry() const override { return whole_.needs_symmetry(); }
  // A new run starts from v = 0 again (its numbers must not depend on the last run's).
  void new_run() override;
  void load_changed() override { scale_ = 0; }
  void start_from(const FluidSolution& last) override;
  void linearise_about(FluidSolution w) override;
  const FluidNewtonReport& report() const { return report_; }
  const NewtonOptions& options() const { return options_; }

 private:
  struct Residual {
    double norm, scale;
    double relative() const { return scale > 0 ? norm / scale : norm; }
  };
  Residual residual(const Eigen::VectorXd& chi, double eps, bool at_rest = false);
  double scale(const Eigen::VectorXd& chi, double eps);
  Residual step(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled, const Residual& r);
  void solve_oseen(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled);
  [[noreturn]] void fail() const;

  StokesAssembler& assembler_;
  WholeSolve whole_;
  FluidTiming& timing_;
  FluidSolution& out_;
  NewtonOptions options_;
  FluidSolution w_;  // the iterate the convection term is linearised about
  std::shared_ptr<NewtonConvection> convection_;
  bool started_ = false;  // w_ holds a solution of this run
  std::optional<FluidSolution> about_;  // semi-implicit: the convecting velocity of the step
  double scale_ = 0;      // ‖b(0)‖, 0 while unknown
  FluidNewtonReport report_;
};

}  // namespace fsi
