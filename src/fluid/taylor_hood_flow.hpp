// The Taylor–Hood fluid solved (fluid.element = "taylor-hood"): Newton's method on
// TaylorHoodSystem's residual (Stokes: one step), BDF1/BDF2 time steps on the fixed
// mesh (SPEC §12), the forces on the holes by the residual method (SPEC §10), and the
// P1 view of the state that the outputs draw and write.
//
// Newton: J δ = −R on the free dofs, damped by halving until the residual falls
// (Armijo's test), and where even a sixteenth does not help, a Picard (Oseen) step
// instead, as the mini element's NewtonSolve; converged when ‖R_free‖ ≤ tol · scale,
// scale the residual's norm at the data's own lifted state (U = 0 but the prescribed
// values). The Jacobian's pattern is analysed once ("mumps-lu").
//
// In time steps the last Newton Jacobian's factors are reused (the chord method) while
// they contract the residual fast: from one Δt to the next the Jacobian moves by
// O(Δt) in its convection only, and a factorisation is three quarters of a Newton step
// (docs/performance.md), so most steps need a back-substitution and a residual each.
// A chord step that does not halve the residual is taken back for a Newton step with a
// fresh Jacobian; one that does not cut it tenfold is kept but its factors are not. The
// answer is the same (the same test ‖R_free‖ ≤ tol · scale); checkpoints keep the state
// the factors were computed at, so that a resumed run reuses the very same factors.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "fluid/fluid_field.hpp"        // FluidValue
#include "fluid/fluid_time_stepper.hpp"  // TimeScheme, BdfWeights, FluidSolution
#include "fluid/newton_solve.hpp"       // FluidNewtonReport
#include "fluid/sparse_solver.hpp"
#include "fluid/taylor_hood_system.hpp"

namespace fsi {

// Where a solve's time goes (summary.json's fluid.assembly_s, ...), over the run.
struct TaylorHoodTiming {
  double assembly = 0, factorization = 0, solve = 0;  // seconds; the analysis is in factorization
  std::vector<int> linear_iterations;  // an iterative linear solver's, per solve
};

struct TaylorHoodOptions {
  double tol = 1e-10;
  int max_steps = 30;
  std::string solver = kNavierStokesSolver;  // factors unsymmetric matrices
  LinearSolverOptions linear;                // an iterative solver's controls
  bool reuse_factors = true;                 // chord steps in time steps (above)
};

class TaylorHoodFlow {
 public:
  explicit TaylorHoodFlow(TaylorHoodSystem& system, const TaylorHoodOptions& options = {});

  TaylorHoodSystem& system() { return system_; }
  // The steady solution for the system's data, Newton from the current state.
  // SolverFailure with the residual history if it does not converge.
  const Eigen::VectorXd& solve();

  // Time: ρ_F ∂v/∂t by `scheme`, from `initial` (a dof vector) at t0, then steps of Δt;
  // data(t) sets the data at the new time before each (may be empty).
  void start(double rho, TimeScheme scheme, double dt, const Eigen::VectorXd& initial, double t0 = 0);
  const Eigen::VectorXd& step(const std::function<void(double)>& data = {});
  // A resumed run: `steps` taken, the last two states.
  void restore(int steps, const Eigen::VectorXd& u_n, const Eigen::VectorXd& u_nm1);
  // The state and mass coefficient the reusable factors were computed at (false: none),
  // and those factors recomputed from them (a resumed run).
  bool factors_state(Eigen::VectorXd& U, double& mass) const;
  void restore_factors(const Eigen::VectorXd& U, double mass);
  double time() const { return t0_ + steps_ * dt_; }
  int steps() const { return steps_; }

  const Eigen::VectorXd& state() const { return U_; }
  const Eigen::VectorXd& previous() const { return U_nm1_; }
  // The force of the fluid on each boundary of `labels` (N per metre): −Σ of the
  // momentum residual's rows at its P2 nodes, at the state and with the data and the
  // time derivative of its solve (one assembly for all).
  std::vector<Point> forces(const std::vector<int>& labels);
  // The state at the vertices (v1, v2, p; no bubbles): what fluid.vtu and the pictures
  // show. P2's midpoint values are not in it.
  FluidSolution vertex_view() const;
  // The velocity and pressure at a point of triangle t given by its barycentric
  // coordinates in the straight triangle: the isoparametric map inverted by Newton's
  // method where t is curved, then P2 and P1 there.
  FluidValue at(int t, const Eigen::Vector3d& straight_lambda) const;
  const FluidNewtonReport& report() const { return report_; }
  int factorizations() const { return solver_->factorizations(); }
  int chord_steps() const { return chord_steps_; }  // over the run: steps on reused factors
  int analyses() const { return solver_->analyses(); }
  std::string solver_name() const { return solver_->name(); }
  const TaylorHoodOptions& options() const { return options_; }
  const TaylorHoodTiming& timing() const { return timing_; }

 private:
  double residual_norm(const Eigen::VectorXd& U);
  // Assembles R(U) into R_ and the Jacobian at U (Newton's, or Picard's), factorises it.
  void factorize_at(const Eigen::VectorXd& U, bool picard);
  // δ = −J⁻¹ R_ with the current factors.
  Eigen::VectorXd back_substitute();
  // J δ = −R(U_) (Newton's J, or Picard's).
  Eigen::VectorXd newton_direction(bool picard);
  // One step from U_ at relative residual r; returns the new one.
  double step_from(double r, double scale);
  // A chord step on the kept factors; false (U_ unchanged) if it does not contract enough.
  bool chord_step(double& r, double scale);
  bool factors_usable() const;
  [[noreturn]] void fail() const;

  TaylorHoodSystem& system_;
  TaylorHoodOptions options_;
  std::unique_ptr<SparseDirectSolver> solver_;
  bool analysed_ = false;
  struct Factors {  // what the solver's current factors are of
    bool newton = false;  // a Newton Jacobian (not Picard's)
    Eigen::VectorXd U;
    double mass = 0;
    long revision = -1;
  } factors_;
  bool reuse_ = false;  // time steps: chord steps allowed
  int chord_steps_ = 0;
  Eigen::VectorXd U_, U_nm1_, R_;
  TimeScheme scheme_ = TimeScheme::bdf1;
  double dt_ = 0, t0_ = 0, rho_ = 0;
  int steps_ = 0;
  FluidNewtonReport report_;
  TaylorHoodTiming timing_;
};

// Errors of a Taylor–Hood state against an exact flow (manufactured solutions): the
// velocity in L² and H¹ (seminorm), the pressure in L² after removing each one's mean
// when `pressure_mean` (pure Dirichlet problems fix p up to a constant).
struct TaylorHoodErrors {
  double velocity_l2 = 0, velocity_h1 = 0, pressure_l2 = 0;
};
TaylorHoodErrors taylor_hood_errors(const TaylorHoodSystem& system, const Eigen::VectorXd& U,
                                    const std::function<Point(const Point&)>& v,
                                    const std::function<Eigen::Matrix2d(const Point&)>& grad_v,
                                    const std::function<double(const Point&)>& p, bool pressure_mean = false);

}  // namespace fsi
