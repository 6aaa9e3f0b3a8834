// What a coupling loop records and returns (FixedPointLoop, SPEC §5): one record per
// pass, the result with the last good state, and the warning a suspicious stop gets.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

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
  int newton_steps = 0;  // a nonlinear structure's Newton steps in this pass (0: linear)
  // fluid.method = "body-fitted" (BodyFittedStep): the pass's fluid mesh and the
  // time to make it (0 for the penalised method's fixed mesh).
  int fluid_triangles = 0;
  bool remeshed = false;  // a new Gmsh mesh (else the last one moved with the structure)
  double t_mesh = 0;
  // What the run's PassObserver read off this pass's ũ (run/: ũ at output.probes).
  std::vector<Point> probes = {};
};

// Called by the loop with each pass's ũ^{k+1} and its record, before the record is
// kept: the run measures ũ there without the loop knowing what it measures.
using PassObserver = std::function<void(const Eigen::VectorXd& u_tilde, IterationRecord& rec)>;

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

}  // namespace fsi
