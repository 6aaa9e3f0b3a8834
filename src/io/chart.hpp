// x–y charts (log or linear axes, several series, a legend) drawn with Cairo, for the
// plots in docs/ (e.g. time per iteration against unknowns).
#pragma once

#include <string>
#include <vector>

#include "io/figure.hpp"

namespace fsi {

struct Series {
  std::string label;
  std::vector<double> x, y;
  Rgb colour{0.1, 0.3, 0.7};
  bool line = true;     // join the points
  bool markers = true;
  bool dashed = false;
};

struct ChartOptions {
  std::string title, x_label, y_label;
  bool log_x = true, log_y = true;
  int width = 900, height = 600;
};

// Writes the chart as a PNG (atomically). Non-positive values are skipped on log axes.
void write_chart(const std::string& path, const ChartOptions& options, const std::vector<Series>& series);

}  // namespace fsi
