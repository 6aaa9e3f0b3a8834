// fsicontact converge: the case on successively refined levels (every size key divided
// by the ratio r, ε following coupling.eps_rule), and per quantity of interest the
// values, the observed order, the Richardson extrapolation and the Grid Convergence
// Index (study/richardson.hpp); with several coupling schemes, whether they land on
// the same state at every level.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "run/outputs/summary.hpp"
#include "run/run_case.hpp"

namespace fsi {

struct ConvergeOptions {
  std::vector<std::string> overrides;  // --set, applied to every level
  int levels = 3;
  double ratio = 2;
  std::string out_dir;                 // default out/<name>-converge
  // The coupling schemes run at every level; the first gives the study's values, the
  // others are compared with it. Empty: the case's scheme only.
  std::vector<std::string> schemes;
  std::string refine = "all";          // "all" | "fluid" | "structure" (study/levels.hpp)
  std::function<void(const std::string&)> progress;
  // Each run of the study as it ends, with its directory (<out>/level-2,
  // level-1-aitken, level-3-eps), with its final fields if keep_fields (the Python
  // module's converge; the study keeps no fields itself).
  std::function<void(const std::string& dir, const RunResult&)> on_run;
  bool keep_fields = false;
};

struct ConvergeResult {
  int exit_status = 0;  // 0 every level converged, 1 a level failed, 3 a level at its limit
  Json summary;
  std::string report;   // the table, for stdout
  std::string out_dir;
};

// Validates everything first (the options, every level's case and meshes: InputError,
// nothing written), then runs the levels coarsest first, each in <out>/level-i, and
// writes <out>/convergence.{csv,md,png} and <out>/summary.json.
ConvergeResult run_convergence(const CaseSource& source, const ConvergeOptions& options);

}  // namespace fsi
