// What a refinement study writes: per level its sizes and run, per quantity its values
// and the estimates (convergence.csv, convergence.md, convergence.png, summary.json).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "run/run_case.hpp"
#include "study/levels.hpp"
#include "study/quantities.hpp"
#include "study/least_squares.hpp"
#include "study/penalty_error.hpp"
#include "study/richardson.hpp"

namespace fsi {

struct LevelRun {
  LevelSpec spec;
  RunResult result;   // summary null if not run
  std::string status = "not run";
  double wall_s = NAN;
};

struct QuantityStudy {
  Quantity quantity;
  std::vector<double> values;       // the study's scheme, coarsest level first
  ConvergenceEstimate estimate;
  LeastSquaresEstimate least_squares;  // four levels or more
  // The finest value's error bar (absolute): the GCI where the finest levels are in
  // the asymptotic range (or three levels converge monotonically); with four levels or
  // more otherwise, the least-squares uncertainty; for three oscillating levels the
  // range bound of richardson.hpp. NaN: none can be given (diverging).
  // With a penalty check (penalised fluid), error_bar = error_bar_h + penalty.error_bar
  // (study/penalty_error.hpp) and error_bar_method ends in " + penalty".
  double error_bar = NAN;
  std::string error_bar_method;  // "GCI" | "least squares" | "oscillation range" (+ " + penalty")
  double error_bar_h = NAN;      // the levels' part alone
  PenaltyError penalty;          // the penalty's part (NaN without a check)
  // U_ε > U_h: the finest level is not in the asymptotic range of both parameters,
  // whatever the levels' orders say (estimate.asymptotic is then false).
  bool penalty_dominates = false;
  // Other schemes: per level the largest |φ_scheme − φ| between converged runs (NaN:
  // none converged beside the study's own, or the quantity is missing).
  std::vector<double> scheme_difference;
  double max_scheme_difference = NAN;
  bool schemes_agree = true;        // every difference ≤ agreement_allowed
  // What coupling.tol leaves undecided in this quantity: the relative change the
  // stopping test lets pass, tol / ‖ũ‖_{L²(Ω_S0)} at the finest level, times |φ|
  // (0 without a fluid).
  double coupling_floor = 0;
};

// Where a scheme ended apart from the study's scheme at a level, that scheme rerun
// from the study's end state (issue 12, item 5): does it stay there?
struct Restart {
  LevelRun run;          // its spec: the other scheme's level, output dir "<dir>-restart"
  std::string from;      // the study's scheme, whose end state is u⁰
  double start = NAN;    // max |u| of that end state
  double own = NAN;      // max |u| of the scheme's own run from rest
  double value = NAN;    // max |u| where the restart ended
  std::string verdict;   // what that says (judge_restart in convergence_report.cpp)
};

struct Study {
  double ratio = 2;
  int levels = 0;
  std::string refine = "all";        // which meshes the levels refine
  std::vector<std::string> schemes;
  std::vector<LevelRun> runs;        // level-major: level 1's schemes, then level 2's, ...
  std::vector<QuantityStudy> quantities;
  std::vector<Restart> restarts;
  // The finest level of the study's scheme again with ε·ratio² (penalised fluid only;
  // status "not run" otherwise).
  LevelRun penalty_check;
  double tol_used = NAN, tol_advised = NAN;  // coupling.tol against 1e-3 of max |u|'s GCI (m²)
};

// Values, estimates and scheme differences from the runs.
void evaluate(Study& study, const Case& base);

// The largest difference between schemes that counts as agreement for q: 0.1 of its
// GCI, or 1e-6 |φ| where there is no GCI; never below its coupling_floor (two runs
// stopped by the same test need not agree better than the test can tell).
double agreement_allowed(const QuantityStudy& q);

// The study's runs of one scheme, coarsest level first.
std::vector<const LevelRun*> runs_of(const Study& s, const std::string& scheme);

// Sets r.verdict from r's values and status.
void judge_restart(Restart& r, double allowed);

// "" or why coupling.tol is too coarse for the study (tol_used > tol_advised).
std::string tolerance_note(const Study& study);
std::string convergence_csv(const Study& study);
std::string convergence_markdown(const Study& study);
void write_convergence_png(const std::string& path, const Study& study);
Json convergence_json(const Study& study);

}  // namespace fsi
