#include "mesh/geo_script.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "common/input_file.hpp"
#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// Gmsh 4.8's commands that act outside the model (its parser, Gmsh.y "Command" and
// the lexer's keywords): programs, files read or written, the GUI, sleeping, exiting.
constexpr std::array<std::string_view, 20> kRefused = {
    "System",   "SystemCall",   "NonBlockingSystemCall", "OnelabRun", "OnelabAction",
    "Include",  "Merge",        "MergeWithBoundingBox",  "ShapeFromFile", "ListFromFile",
    "Save",     "Print",        "CreateDir",             "DeleteFile",    "RenameFile",
    "Sleep",    "Exit",         "Abort",                 "Plugin",        "Draw"};

// Message commands that may redirect their text to a file: Printf("...") > "file";
constexpr std::array<std::string_view, 3> kRedirectable = {"Printf", "Error", "Warning"};

bool starts_identifier(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool in_identifier(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A scanner of the script's text that sees what Gmsh's lexer sees: comments and
// strings skipped (so "Save" in a comment or a physical name is harmless).
class Scanner {
 public:
  Scanner(const std::string& text, const std::string& path) : text_(text), path_(path) {}

  void run() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '/' && next() == '/') skip_until("\n");
      else if (c == '/' && next() == '*') i_ += 2, skip_until("*/");
      else if (c == '"' || c == '\'') ++i_, skip_until(std::string(1, c));
      else if (starts_identifier(c)) identifier();
      else advance();
    }
  }

 private:
  char next() const { return i_ + 1 < text_.size() ? text_[i_ + 1] : '\0'; }
  void advance() {
    if (text_[i_] == '\n') ++line_;
    ++i_;
  }
  void skip_until(const std::string& end) {
    while (i_ < text_.size() && text_.compare(i_, end.size(), end) != 0) advance();
    i_ = std::min(text_.size(), i_ + end.size());
    if (end == "\n") ++line_;
  }
  void identifier() {
    const std::size_t start = i_;
    while (i_ < text_.size() && in_identifier(text_[i_])) ++i_;
    const std::string_view word(text_.data() + start, i_ - start);
    // A word after '.' is an option's or a field's name (Mesh.Algorithm), one before
    // '.' an option category (Print.Format = 1): neither is a command.
    std::size_t after = i_;
    while (after < text_.size() && (text_[after] == ' ' || text_[after] == '\t')) ++after;
    const bool option = (start > 0 && text_[start - 1] == '.') || (after < text_.size() && text_[after] == '.');
    if (!option && std::find(kRefused.begin(), kRefused.end(), word) != kRefused.end())
      refuse(word, "it reaches outside the geometry (runs a program, reads or writes a file, waits or exits)");
    if (!option && std::find(kRedirectable.begin(), kRedirectable.end(), word) != kRedirectable.end() &&
        redirects())
      refuse(word, "its '>' writes the message into a file");
  }
  // Whether the statement from here to its ';' has a '>' outside parentheses and strings.
  bool redirects() const {
    int depth = 0;
    for (std::size_t k = i_; k < text_.size(); ++k) {
      const char c = text_[k];
      if (c == '"' || c == '\'') {
        k = text_.find(c, k + 1);
        if (k == std::string::npos) return false;
      } else if (c == '(') {
        ++depth;
      } else if (c == ')') {
        --depth;
      } else if (c == ';') {
        return false;
      } else if (c == '>' && depth <= 0) {
        return true;
      }
    }
    return false;
  }
  [[noreturn]] void refuse(std::string_view word, const std::string& why) const {
    throw MeshError(path_ + ":" + std::to_string(line_) + ": the command '" + std::string(word) +
                    "' is not allowed in a structure script: " + why +
                    "; allowed: geometry, physical groups, mesh sizes, fields and options");
  }

  const std::string& text_;
  const std::string& path_;
  std::size_t i_ = 0;
  int line_ = 1;
};

}  // namespace

void check_geo_script(const std::string& text, const std::string& path) {
  if (text.find('\0') != std::string::npos)
    throw MeshError(path + ": is not a text file (it holds a NUL byte); allowed: a Gmsh .geo script");
  Scanner(text, path).run();
}

std::string read_geo_script(const std::string& path) {
  namespace fs = std::filesystem;
  if (const std::string problem = input_file_problem(path, "script", "a Gmsh .geo file"); !problem.empty())
    throw MeshError(path + ": " + problem);
  std::error_code ec;
  if (fs::path(path).extension() != ".geo")
    throw MeshError(path + ": a structure script must be a Gmsh .geo file (the extension .geo)");
  const auto size = fs::file_size(path, ec);
  if (ec || size > kMaxGeoScriptBytes)
    throw MeshError(path + ": is " + std::to_string(size) + " bytes; allowed: at most " +
                    std::to_string(kMaxGeoScriptBytes));
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw MeshError(path + ": cannot be read");
  std::string s = text.str();
  check_geo_script(s, path);
  return s;
}

}  // namespace fsi
