// The rows file of a sweep: RFC 4180 CSV (commas, double quotes with "" for a quote
// inside), plus blank lines and lines starting with '#' skipped.
#pragma once

#include <string>
#include <vector>

namespace fsi {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> line_of_row;  // the file's line number of each row, for messages
};

// Throws InputError "<path>:<line>: ...; allowed: ..." for an unreadable file, an
// unterminated quote, a row with the wrong number of cells, no header or no row.
CsvTable read_csv(const std::string& path);

}  // namespace fsi
