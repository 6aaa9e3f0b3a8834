#include "run/outputs/output_dir.hpp"

#include <algorithm>
#include <filesystem>

#include "common/errors.hpp"
#include "common/launch.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"
#include "run/provenance.hpp"

namespace fsi {

const std::vector<std::string>& output_file_names() {
  static const std::vector<std::string> names = {"summary.json", "case.toml",     "history.csv",  "fluid.vtu",
                                                 "structure.vtu", "fsi.pvd",      "fsi.png",      "fluid.png",
                                                 "structure.png", "table.md",     "table.csv",
                                                 "convergence.csv", "convergence.md", "convergence.png",
                                                 "fluid.pvd",    "fluid-wake.png", "structure.pvd",
                                                 "checkpoint.bin", "animation.gif"};
  return names;
}

int frame_step(const std::string& file) {
  for (const char* prefix : {"fluid-", "structure-", "frame-"}) {
    const std::size_t n = std::char_traits<char>::length(prefix);
    if (file.rfind(prefix, 0) != 0 || file.size() != n + 10) continue;
    int step = 0;
    for (std::size_t i = n; i < n + 6; ++i) {
      if (file[i] < '0' || file[i] > '9') return -1;
      step = 10 * step + (file[i] - '0');
    }
    const std::string ext = file.substr(n + 6);
    return ext == ".vtu" || ext == ".png" ? step : -1;
  }
  return -1;
}

void remove_stale_outputs(const std::string& dir, const std::string& keep, int keep_frames_to, bool keep_checkpoint) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    const int step = frame_step(file);
    bool is_stale = step > keep_frames_to;
    const std::size_t tmp = file.find(".tmp");
    if (tmp != std::string::npos && frame_step(file.substr(0, tmp)) >= 0 && is_temporary_of(file, file.substr(0, tmp)))
      is_stale = true;
    for (const std::string& name : output_file_names())
      if ((file == name && name != keep && !(keep_checkpoint && name == "checkpoint.bin")) ||
          is_temporary_of(file, name))
        is_stale = true;
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

void RunOutputs::begin(Json header, std::optional<int> resumed_frames_to) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw OutputError(dir_, ec.value());
  header["status"] = "writing";
  header["program"] = provenance_json();
  write_json(path("summary.json"), header);  // first: the directory now says it is in flux
  remove_stale_outputs(dir_, "summary.json", resumed_frames_to.value_or(-1), resumed_frames_to.has_value());
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
  summary["program"] = provenance_json();  // what made it (issue 31)
  summary["ranks"] = launched_ranks();       // SPEC §13
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
