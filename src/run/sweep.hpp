// fsicontact sweep: one run per row of a CSV whose column headers are case keys
// (section.key); columns "paper.*" are reference values shown beside ours (SPEC §8).
#pragma once

#include <string>
#include <vector>

#include "run/run_case.hpp"

namespace fsi {

struct SweepOptions {
  std::vector<std::string> overrides;  // applied to every row before the row's own
  std::string out_dir;                 // default out/<case name>-sweep
  bool keep_outputs = false;           // per-row .vtu/.png (off: summary and history only)
  std::function<void(const std::string&)> progress;
};

struct SweepResult {
  int rows = 0, converged = 0, not_converged = 0, failed = 0;
  bool interrupted = false;  // Ctrl-C: the table holds the rows run so far
  std::string out_dir;
  std::string table_markdown;
};

// Validates every row first (InputError, nothing written), then runs them in order.
SweepResult run_sweep(const std::string& case_path, const std::string& rows_csv, const SweepOptions& options);

// A CSV file as header + rows of cells (commas, optional double quotes, # comments).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};
CsvTable read_csv(const std::string& path);

}  // namespace fsi
