// A time run's history.csv read back: its header's columns and every row's numbers.
#pragma once

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace fsi::testing {

struct History {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::size_t column(const std::string& name) const {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  }
  // Column `name` of every row.
  std::vector<double> values(const std::string& name) const {
    std::vector<double> v;
    const std::size_t c = column(name);
    for (const auto& row : rows) v.push_back(c < row.size() ? row[c] : NAN);
    return v;
  }
};

inline History read_history(const std::filesystem::path& file) {
  History h;
  std::istringstream in(slurp(file));
  std::string line;
  std::getline(in, line);
  std::istringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) h.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<double> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(std::stod(cell));
    h.rows.push_back(cells);
  }
  return h;
}

}  // namespace fsi::testing
