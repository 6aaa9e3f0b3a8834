#include "run/outputs/output_dir.hpp"

#include <algorithm>
#include <filesystem>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"

namespace fsi {

const std::vector<std::string>& output_file_names() {
  static const std::vector<std::string> names = {"summary.json", "case.toml",     "history.csv",  "fluid.vtu",
                                                 "structure.vtu", "fsi.pvd",      "fsi.png",      "fluid.png",
                                                 "structure.png", "table.md",     "table.csv",
                                                 "convergence.csv", "convergence.md", "convergence.png",
                                                 "fluid.pvd",    "fluid-wake.png"};
  return names;
}

namespace {

// A time run's frame fluid-NNNNNN.vtu (run/time_fluid_problem.cpp), or its temporary.
bool is_frame_output(const std::string& file) {
  if (file.rfind("fluid-", 0) != 0 || file.size() < 16) return false;
  for (std::size_t i = 6; i < 12; ++i)
    if (file[i] < '0' || file[i] > '9') return false;
  return file.compare(12, 4, ".vtu") == 0;
}

}  // namespace

void remove_stale_outputs(const std::string& dir, const std::string& keep) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    bool is_stale = is_frame_output(file);
    for (const std::string& name : output_file_names())
      if ((file == name && name != keep) || is_temporary_of(file, name)) is_stale = true;
    if (is_stale) stale.push_back(it->path());
  }
  for (const auto& p : stale)
    if (!fs::is_directory(fs::symlink_status(p, ec))) fs::remove(p, ec);
}

void remove_stale_subdirs(const std::string& dir, const std::string& prefix, const std::vector<std::string>& keep) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) == 0 && std::find(keep.begin(), keep.end(), name) == keep.end() &&
        fs::is_directory(fs::symlink_status(it->path(), ec)))
      stale.push_back(it->path());
  }
  for (const auto& p : stale) {
    remove_stale_outputs(p.string());
    fs::remove(p, ec);  // only if now empty
  }
}

void RunOutputs::begin(Json header) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw OutputError(dir_, ec.value());
  header["status"] = "writing";
  write_json(path("summary.json"), header);  // first: the directory now says it is in flux
  remove_stale_outputs(dir_, "summary.json");
}

bool RunOutputs::write(const std::string& name, const std::function<void(const std::string& path)>& writer) {
  try {
    writer(path(name));
    return true;
  } catch (const OutputError& e) {
    errors_.push_back(e.what());
    return false;
  }
}

Json RunOutputs::finish(Json summary) {
  if (failed()) {
    if (summary.contains("status")) summary["solve_status"] = summary["status"];
    summary["status"] = "failed";
    const std::string solve_failure = summary.contains("failure") ? summary["failure"].get<std::string>() + "; " : "";
    summary["failure"] = solve_failure + "writing the outputs: " + failure();
  }
  write_json(path("summary.json"), summary);
  return summary;
}

std::string RunOutputs::failure() const {
  std::string all;
  for (const auto& e : errors_) all += (all.empty() ? "" : "; ") + e;
  return all;
}

std::string RunOutputs::path(const std::string& name) const {
  return (std::filesystem::path(dir_) / name).string();
}

void write_case_toml(RunOutputs& out, const Case& c) {
  out.write("case.toml", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << to_toml(c); }); });
}

}  // namespace fsi
