#include "run/csv.hpp"

#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "common/input_file.hpp"

namespace fsi {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// One line's cells; false if a quote is left open (a quoted cell may not span lines).
bool split_csv_line(const std::string& line, std::vector<std::string>& cells) {
  cells.clear();
  std::string cell;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch != '"') cell += ch;
      else if (i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;  // "" is a quote
      else quoted = false;
    } else if (ch == '"') {
      quoted = was_quoted = true;
    } else if (ch == ',') {
      cells.push_back(was_quoted ? cell : trim(cell));
      cell.clear();
      was_quoted = false;
    } else {
      cell += ch;
    }
  }
  cells.push_back(was_quoted ? cell : trim(cell));
  return !quoted;
}

}  // namespace

CsvTable read_csv(const std::string& path) {
  if (const std::string problem = input_file_problem(path, "rows", "a CSV file of section.key columns"); !problem.empty())
    throw InputError(path + ": " + problem);
  std::ifstream in(path);
  if (!in) throw InputError(path + ": no such rows file");
  CsvTable t;
  std::string line;
  std::vector<std::string> cells;
  for (int number = 1; std::getline(in, line); ++number) {
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    if (!split_csv_line(line, cells))
      throw InputError(path + ":" + std::to_string(number) + ": a quote is not closed; allowed: \"...\" within one line");
    if (t.header.empty()) {
      t.header = cells;
      continue;
    }
    if (cells.size() != t.header.size())
      throw InputError(path + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                       " cells; allowed: " + std::to_string(t.header.size()) + " (one per header column)");
    t.rows.push_back(cells);
    t.line_of_row.push_back(number);
  }
  if (in.bad()) throw InputError(path + ": cannot be read");
  if (t.header.empty()) throw InputError(path + ": empty rows file; allowed: a header line and rows");
  if (t.rows.empty()) throw InputError(path + ": a header and no rows; allowed: at least one row to run");
  return t;
}

}  // namespace fsi
