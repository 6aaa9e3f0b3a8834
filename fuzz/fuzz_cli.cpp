// libFuzzer target: the whole command line, in-process (app/cli.cpp), on small
// problems. An input is a little archive of sections:
//   --- args        one argument per line ("run", "case.toml", "--set", "k=v", ...)
//   --- case.toml   the files the arguments may name: case.toml, rows.csv,
//   --- beam.msh    beam.msh, box.msh, s.geo (a structure script: nothing else is written)
// Contract (SPEC §8, issue 11), checked after every input:
//   - the exit status is 0, 1, 2 or 3 and no exception escapes;
//   - status 2: nothing at all was created;
//   - a run that exits 0, 1 or 3 leaves summary.json whose status matches it
//     (converged, failed, iteration limit); a sweep leaves its summary.json;
//   - no temporary file (*.tmp<pid>) is left anywhere.
// Everything happens in a scratch directory: --out values are kept inside it (an
// absolute path gets a prefix, a ".." component is renamed), and a run without
// --out gets one, so that output.dir in a case file cannot point elsewhere.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "common/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"
#include "run/outputs/output_dir.hpp"

namespace {

namespace fs = std::filesystem;

const std::set<std::string> kFiles = {"case.toml", "rows.csv", "beam.msh", "box.msh", "s.geo"};

struct Input {
  std::vector<std::string> args;
  std::vector<std::pair<std::string, std::string>> files;
};

Input parse(const std::string& text) {
  Input in;
  std::istringstream lines(text);
  std::string line, section;
  std::string* file = nullptr;
  while (std::getline(lines, line)) {
    if (line.rfind("--- ", 0) == 0) {
      section = line.substr(4);
      file = nullptr;
      if (kFiles.count(section)) file = &in.files.emplace_back(section, "").second;
      continue;
    }
    // An argument is a C string: it ends at a NUL, as the kernel would end it.
    if (section == "args" && in.args.size() < 40) in.args.push_back(line.substr(0, std::min<std::size_t>(4096, line.find('\0'))));
    else if (file) *file += line + "\n";
  }
  return in;
}

// A path inside the scratch directory, whatever the fuzzer wrote.
std::string confine(const std::string& path) {
  std::string out;
  std::istringstream parts(path);
  for (std::string part; std::getline(parts, part, '/');)
    out += (out.empty() && path[0] != '/' ? "" : "/") + (part == ".." ? std::string("dotdot") : part);
  return path.empty() || path[0] != '/' ? out : "abs" + out;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(e.path().string());
  return names;
}

nlohmann::json summary_in(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) __builtin_trap();  // a run or sweep that ended without its summary
  return nlohmann::json::parse(in);
}

struct NullBuffer : std::streambuf {
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Small problems: each input runs in milliseconds (fluid meshes of hF >= ~0.015 on
  // the paper's box).
  fsi::case_limits() = {.structure_triangles = 2000, .fluid_triangles = 6000, .fluid_triangles_iterative = 6000,
                        .max_iterations = 30, .time_steps = 30};
  static const fs::path scratch = fs::temp_directory_path() / ("fsicontact-fuzz-cli-" + std::to_string(::getpid()));
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  fs::current_path(scratch);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Input in = parse(std::string(reinterpret_cast<const char*>(data), size));
  for (const auto& e : fs::directory_iterator(".")) fs::remove_all(e.path());
  for (const auto& [name, text] : in.files) std::ofstream(name, std::ios::binary) << text;

  std::vector<std::string> args = {"fsicontact"};
  std::string command, out_dir;
  for (std::size_t i = 0; i < in.args.size(); ++i) {
    std::string a = in.args[i];
    if (command.empty() && (a == "run" || a == "sweep")) command = a;
    if (a.rfind("--out=", 0) == 0) a = "--out=" + (out_dir = confine(a.substr(6)));
    args.push_back(a);
    if (a == "--out" && i + 1 < in.args.size()) args.push_back(out_dir = confine(in.args[++i]));
  }
  if (!command.empty() && out_dir.empty()) args.insert(args.end(), {"--out", out_dir = "o/default"});
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());

  const std::set<std::string> before = listing(".");
  NullBuffer null;
  std::ostream quiet(&null);
  std::ostringstream out;  // to tell a help text (-h, -hq, --help ...) from a run
  fsi::clear_interrupt();
  int status = -1;
  try {
    status = fsi::fsicontact_main(static_cast<int>(argv.size()), argv.data(), out, quiet);
  } catch (...) {
    __builtin_trap();  // nothing may escape the command line
  }
  const bool help = out.str().find("Usage:") != std::string::npos;
  if (status < 0 || status > 3) __builtin_trap();
  if (status == 2 && listing(".") != before) __builtin_trap();  // invalid input wrote something
  for (const auto& name : listing("."))
    for (const std::string& output : fsi::output_file_names())
      if (fsi::is_temporary_of(fs::path(name).filename().string(), output)) __builtin_trap();  // a temporary left
  if (status != 2 && !help && !command.empty() && !out_dir.empty() && fs::is_directory(out_dir)) {
    const nlohmann::json j = summary_in(out_dir);
    if (command == "sweep" && j.value("status", "") != "complete") __builtin_trap();
    if (command == "run") {
      const std::string s = j.value("status", "");
      if ((status == 0 && s != "converged") || (status == 3 && s != "iteration limit") || (status == 1 && s != "failed"))
        __builtin_trap();
    }
  } else if (status != 2 && !help && !command.empty() && !out_dir.empty()) {
    __builtin_trap();  // exit 0, 1 or 3 without an output directory
  }
  return 0;
}
