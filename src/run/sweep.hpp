// fsicontact sweep: one run per row of a CSV whose column headers are case keys
// (section.key); columns "paper.*" are reference values shown beside ours, "label"
// names a row (SPEC §8).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/run_case.hpp"

namespace fsi {

struct SweepOptions {
  std::vector<std::string> overrides;  // applied to every row before the row's own
  std::string out_dir;                 // default out/<case name>-sweep
  bool keep_outputs = false;           // per-row .vtu/.png (off: summary and history only)
  std::function<void(const std::string&)> progress;
  // Each row's result as it ends (its index in the file's order, its directory), with
  // its final fields if keep_fields (the Python module's sweep).
  std::function<void(std::size_t row, const std::string& dir, const RunResult&)> on_row;
  bool keep_fields = false;
};

struct SweepResult {
  int rows = 0, converged = 0, not_converged = 0, failed = 0;
  int interrupted_by = 0;  // the signal that stopped the sweep (0: none); the tables hold the rows run
  std::string out_dir;
  std::string table_markdown;
  // 128 + signal if interrupted; else 1 if a row failed; else 3 if a row reached its
  // iteration limit; else 0 (docs/cases.md, "Exit status").
  int exit_status() const;
};

// Validates everything first: the CSV (headers known, no duplicate, at least one
// row), every row's case, the output directory and every row's meshes (InputError
// naming the file and row: nothing written). Then runs the rows, each writing its
// own directory row-NN, and writes table.md, table.csv and the sweep's summary.json.
SweepResult run_sweep(const CaseSource& source, const std::string& rows_csv, const SweepOptions& options);

}  // namespace fsi
