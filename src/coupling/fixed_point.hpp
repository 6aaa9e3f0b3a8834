// The paper's fixed-point algorithm (§6, SPEC §5): given u^k,
//   χ from φ^k(Ω_S0) → fluid solve → force (eq. 33) → contact QP → ũ^{k+1},
//   stop if ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)} < tol, else u^{k+1} = relaxation(u^k, ũ^{k+1}).
// State lives here; the pieces it calls are built once by the caller.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "coupling/force_transfer.hpp"
#include "coupling/relaxation.hpp"
#include "fluid/chi.hpp"
#include "fluid/penalised_stokes.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

struct IterationRecord {
  int iteration = 0;          // 1, 2, ... (passes through steps 2–5)
  double increment = 0;       // ‖ũ^{k+1} − u^k‖_{L²(Ω_S0)}
  double omega = std::numeric_limits<double>::quiet_NaN();  // factor applied after this pass
                                                            // (NaN: none, or an IQN-ILS step)
  int active_nodes = 0;
  int chi_triangles = 0;      // fluid triangles with χ > 0
  bool fluid_reused = false;  // χ unchanged: previous fluid solution reused
  double t_chi = 0, t_fluid = 0, t_transfer = 0, t_structure = 0;
  // fluid.method = "body-fitted" (BodyFittedCoupling): the pass's fluid mesh and the
  // time to make it (0 for the penalised method's fixed mesh).
  int fluid_triangles = 0;
  bool remeshed = false;  // a new Gmsh mesh (else the last one moved with the structure)
  double t_mesh = 0;
};

struct CouplingResult {
  bool converged = false;
  int iterations = 0;
  double final_increment = 0;
  double final_norm = 0;       // ‖ũ‖_{L²(Ω_S0)} of the last ũ, the scale of the increment
  ContactSolution structure;   // the last ũ (the solution if converged)
  Eigen::VectorXd fluid_load;  // eq. (33)'s fluid terms that produced `structure` (empty before)
  std::vector<IterationRecord> history;
  int projections = 0;         // infeasible accelerated updates projected back
  // Set when the loop stopped early: a solve failed (the message names the phase and
  // iteration; `structure` is the last good state) or Ctrl-C was pressed.
  std::string failure;
  bool interrupted = false;
};

// A stop can be a chance dip below tol of increments that never settled (seen with
// ε = 1e-6, constant ω: increments wander between 2e-4 and 4e-3 for 88 passes, then
// one falls to 8e-5). The SPEC's stopping test is kept; this names such a stop: the
// ten increments before the last had a median above 5·tol AND the last is below a
// tenth of the largest of the three before it (an abrupt fall, not a trend).
// It also names a stop that says nothing about convergence: the last increment more
// than a tenth of ‖ũ‖ itself, so that tol (absolute, m²) was coarse for the problem's
// scale (a beam scaled to 3e-13 m "converged" in its first pass, whose increment is
// the whole displacement). Empty if neither.
std::string convergence_warning(const CouplingResult& r, double tol);

class FixedPointCoupling {
 public:
  struct Parts {
    ElasticContactSolver& structure;
    const Eigen::VectorXd& b_applied;  // f_S and h_N part of b_S
    PenalisedStokes& fluid;
    const PointLocator& fluid_locator;
    const ChiComputer& chi;
    const FluidForce& force;
    Relaxation& relaxation;
  };
  FixedPointCoupling(Parts parts, double tol, int max_iterations);

  // One line per iteration (for stderr).
  std::function<void(const std::string&)> progress;
  // Whether run() ends by expanding the last fluid solution to the far field
  // (PenalisedStokes::complete()): the outputs that draw or write the whole fluid
  // need it; a run without them can leave it exact near the structure only.
  bool complete_at_end = true;
  // Called with u^k before each pass's QP: contact.gap = "normal" re-linearises the
  // constraint about the current state there, once per pass (SPEC §9). Empty: the
  // constraint stays as built (the paper's eq. 15).
  std::function<void(const Eigen::VectorXd& u)> relinearise;
  // u⁰ instead of the structure at rest (2nv, feasible: another run's ũ, say). A
  // restart from another scheme's end state tells whether that state is a fixed
  // point for this scheme too (study/converge.cpp).
  Eigen::VectorXd initial;

  // Never throws for a failed solve: it stops, keeps the last good state and says
  // why in CouplingResult::failure (a SolverFailure or QpError in a phase, memory
  // running out, or a field became non-finite). A bug (std::logic_error,
  // std::invalid_argument, ... from our own code) is not a failed solve: it propagates.
  CouplingResult run();

 private:
  void iterate(CouplingResult& result);

  Parts p_;
  double tol_;
  int max_iterations_;
  SparseMatrix M_;  // L²(Ω_S0) mass, for the stopping test
};

}  // namespace fsi
