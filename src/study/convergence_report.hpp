// What a refinement study writes: per level its sizes and run, per quantity its values
// and the estimates (convergence.csv, convergence.md, convergence.png, summary.json).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "run/run_case.hpp"
#include "study/levels.hpp"
#include "study/quantities.hpp"
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
  // Other schemes: per level the largest |φ_scheme − φ| between converged runs (NaN:
  // none converged beside the study's own, or the quantity is missing).
  std::vector<double> scheme_difference;
  double max_scheme_difference = NAN;
  bool schemes_agree = true;        // every difference ≤ 0.1 GCI (≤ 1e-6 |φ| without a GCI)
};

struct Study {
  double ratio = 2;
  int levels = 0;
  std::string refine = "all";        // which meshes the levels refine
  std::vector<std::string> schemes;
  std::vector<LevelRun> runs;        // level-major: level 1's schemes, then level 2's, ...
  std::vector<QuantityStudy> quantities;
  double tol_used = NAN, tol_advised = NAN;  // coupling.tol against 1e-3 of max |u|'s GCI (m²)
};

// Values, estimates and scheme differences from the runs.
void evaluate(Study& study, bool with_fluid);

// "" or why coupling.tol is too coarse for the study (tol_used > tol_advised).
std::string tolerance_note(const Study& study);
std::string convergence_csv(const Study& study);
std::string convergence_markdown(const Study& study);
void write_convergence_png(const std::string& path, const Study& study);
Json convergence_json(const Study& study);

}  // namespace fsi
