// The fluid marched in time on its fixed mesh (SPEC §12): each step sets the data at
// t^{n+1} (a callback: body force, inflow, tractions, χ), the time derivative's
// history (FluidTimeDerivative, BDF1 or BDF2), and solves the steady operator plus
// ρα/Δt once: Stokes by one factorisation, Navier–Stokes by Newton's method from the
// last step's solution (PenalisedStokes::set_navier_stokes, before the first step).
#pragma once

#include <functional>
#include <memory>

#include "fluid/penalised_stokes.hpp"
#include "fluid/time_derivative.hpp"

namespace fsi {

// The fluid at rest on `mesh`: v = 0 (bubbles too) and p = 0 everywhere, the
// prescribed values included (an impulsive start: the first step applies them).
FluidSolution fluid_at_rest(const Mesh& mesh);

class FluidTimeStepper {
 public:
  // Adds the time derivative to `fluid` (kept referenced) and starts from `initial` at t0.
  FluidTimeStepper(PenalisedStokes& fluid, double rho, TimeScheme scheme, double dt, const FluidSolution& initial,
                   double t0 = 0);
  FluidTimeStepper(const FluidTimeStepper&) = delete;
  FluidTimeStepper& operator=(const FluidTimeStepper&) = delete;

  // The solution at t + Δt, which becomes v^n. `data(t_next)` first sets what depends
  // on time (may be empty). Throws SolverFailure (the state stays at t).
  const FluidSolution& step(const std::function<void(double)>& data = {});

  // The same step in parts, for a coupled step whose passes change χ and the
  // penalty's load (SPEC §12): begin() sets the data at t^{n+1} and the history;
  // solve() solves with what the fluid holds now, once per pass, exact at least on
  // `sampled` (null: everywhere; PenalisedStokes::solve); accept() makes the last
  // pass's solution v^{n+1}, completed everywhere (the next step's history needs it).
  // step() is begin, solve, accept.
  void begin(const std::function<void(double)>& data = {});
  const FluidSolution& solve(SampledTriangles sampled = nullptr);
  void accept();
  // v^{n−1} (v^n before the first step) and the BDF weights of the step begun (or next).
  const FluidSolution& previous() const { return *v_nm1_; }
  BdfWeights weights() const { return bdf_weights(scheme_, steps_); }

  // A resumed run (SPEC §12 checkpoints): the state after `steps` steps, v^n and v^{n−1}
  // as the interrupted run had them. last_step_inertia() is null until the next step.
  void restore(int steps, const FluidSolution& v_n, const FluidSolution& v_nm1);

  double time() const { return t0_ + steps_ * dt_; }  // not a running sum: t_end arrives to the digit
  int steps() const { return steps_; }
  double dt() const { return dt_; }
  const FluidSolution& state() const { return *v_n_; }
  // ρ∂v/∂t of the last step taken, its history kept: the residual forces at state()
  // need it (MomentumModel::inertia). Null before the first step.
  const FluidTimeDerivative* last_step_inertia() const { return stepped_ ? derivative_.get() : nullptr; }

 private:
  FluidSolution extrapolated(bool second_order) const;

  PenalisedStokes& fluid_;
  TimeScheme scheme_;
  double dt_, t0_;
  int steps_ = 0;
  bool solved_ = false;  // the step begun has a solution in spare_
  bool stepped_ = false;  // derivative_ holds the last step's history (a step taken since the start or restore)
  std::shared_ptr<FluidTimeDerivative> derivative_;
  // v^n, v^{n−1}, and the buffer the next solution goes to (the last step's v^{n−1},
  // which its time derivative still reads until the next step).
  std::unique_ptr<FluidSolution> v_n_, v_nm1_, spare_;
};

}  // namespace fsi
