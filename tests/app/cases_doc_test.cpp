// docs/cases.md's key table against the case reader (issue 31): every key the reader
// knows (case_keys()) is named in its section's row, and every key the table states
// (a `name` followed by its default, a value or its range) is one the reader knows,
// so the reference and the reader cannot drift apart.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "io/case.hpp"

namespace fsi::cases_doc_test {
namespace {

// Each table row "| `[section]` | ... |" (and "| `[[obstacles]]` |"): section → text.
std::map<std::string, std::string> key_rows() {
  std::ifstream in(std::string(FSICONTACT_SOURCE_DIR) + "/docs/cases.md");
  std::map<std::string, std::string> rows;
  const std::regex row(R"(^\| `\[\[?([a-z]+)\]\]?` \|(.*)$)");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_match(line, m, row)) rows[m[1]] += m[2].str();
  return rows;
}

TEST(CasesDoc, EveryKeyOfTheReaderIsInItsSectionsRow) {
  const auto rows = key_rows();
  ASSERT_GE(rows.size(), 7u) << "docs/cases.md lost its key table";
  for (const std::string& key : case_keys()) {
    const auto dot = key.find('.');
    if (dot == std::string::npos) continue;  // "name": the file's own
    const std::string section = key.substr(0, dot), name = key.substr(dot + 1);
    const auto it = rows.find(section);
    ASSERT_NE(it, rows.end()) << "docs/cases.md has no row for [" << section << "]";
    EXPECT_NE(it->second.find("`" + name + "`"), std::string::npos)
        << key << " is read by the case reader but not in docs/cases.md's [" << section << "] row";
  }
}

// A `name` followed by what a default looks like (a number, a quoted choice, a list,
// a boolean, "none", a path, or "(" opening its meaning) is a key the table states.
TEST(CasesDoc, EveryKeyTheTableStatesIsReadByTheCaseReader) {
  std::set<std::string> known;
  for (const std::string& key : case_keys()) known.insert(key);
  // summary.json's keys that the [time] row describes in the same words.
  for (const char* output : {"time.steps", "time.time", "time.force_min", "time.energy", "time.contact_intervals"})
    known.insert(output);
  const std::regex stated(R"(`([a-z][A-Za-z0-9_]*)` (?=[0-9"\[(−-]|true|false|none|out/))");
  int checked = 0;
  for (const auto& [section, text] : key_rows()) {
    if (section == "obstacles") continue;  // [[obstacles]]' entries: shape, points, normal, ... (checked by its reader)
    for (std::sregex_iterator it(text.begin(), text.end(), stated), end; it != end; ++it, ++checked)
      EXPECT_TRUE(known.count(section + "." + (*it)[1].str()))
          << "docs/cases.md states " << section << "." << (*it)[1] << ", which the case reader does not know";
  }
  EXPECT_GT(checked, 40);
}

}  // namespace
}  // namespace fsi::cases_doc_test
