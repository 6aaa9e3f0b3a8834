// The sweep's tables: our numbers beside the paper's, one line per row (table.md
// for people, table.csv for scripts).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "run/outputs/run_measures.hpp"

namespace fsi {

struct SweepRow {
  Case c;
  std::map<std::string, std::string> paper;  // paper.* reference values (and "label")
  // After the run: what it measured (nothing if not run or failed), status and wall time.
  RunMeasures measures;
  std::string status = "not run (interrupted)";
  double wall_s = NAN;
};

std::string sweep_table_markdown(const std::vector<SweepRow>& rows);
std::string sweep_table_csv(const std::vector<SweepRow>& rows);

}  // namespace fsi
