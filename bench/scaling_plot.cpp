// Draws scaling.png for bench/scaling.sh (which calls it): from scaling.csv, time per
// fixed-point iteration and peak memory against the fluid unknowns N on log-log axes,
// with dashed references ∝ N^1 and ∝ N^1.2 through the first time point and the
// least-squares exponents in the legend. Usage: scaling_plot scaling.csv scaling.png
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/chart.hpp"

namespace {

// The named columns of a CSV file without quoted fields (what scaling.sh writes).
std::map<std::string, std::vector<double>> read_columns(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = split(line);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t i = 0; i < names.size(); ++i)
      columns[names[i]].push_back(i < cells.size() && !cells[i].empty() ? std::strtod(cells[i].c_str(), nullptr) : NAN);
  }
  return columns;
}

// Least-squares slope of log y against log x.
double exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    n += 1, sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: scaling_plot scaling.csv scaling.png\n";
    return 2;
  }
  try {
    auto columns = read_columns(argv[1]);
    const std::vector<double>& n = columns["unknowns"];
    const std::vector<double>& time = columns["time_per_iteration_s"];
    const std::vector<double>& memory = columns["peak_MB"];
    if (n.size() < 2 || time.size() != n.size() || memory.size() != n.size())
      throw std::runtime_error(std::string(argv[1]) + ": needs columns unknowns, time_per_iteration_s, peak_MB and 2 rows");

    const std::vector<double> ends{n.front(), n.back()};
    auto reference = [&](double p) { return std::vector<double>{time.front(), time.front() * std::pow(n.back() / n.front(), p)}; };
    const std::vector<fsi::Series> series{
        {"time per iteration (s), fit N^" + fixed(exponent(n, time), 2), n, time, {0.1, 0.3, 0.7}},
        {"peak memory (MB), fit N^" + fixed(exponent(n, memory), 2), n, memory, {0.8, 0.2, 0.1}},
        {"reference N^1", ends, reference(1.0), {0.4, 0.4, 0.4}, true, false, true},
        {"reference N^1.2", ends, reference(1.2), {0.2, 0.6, 0.3}, true, false, true},
    };
    fsi::ChartOptions options;
    options.title = "Coupled run (Table 1 row 2) against the fluid mesh";
    options.x_label = "fluid unknowns N";
    options.y_label = "time per iteration (s), peak memory (MB)";
    fsi::write_chart(argv[2], options, series);
  } catch (const std::exception& e) {
    std::cerr << "scaling_plot: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
