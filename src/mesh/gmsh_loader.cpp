// Loads libfsicontact_gmsh.so (gmsh_model.hpp) on first use, from where the program
// (or the module holding this code: the Python module) lives: <dir>/../lib/fsicontact/,
// the layout of both the build tree (build/app/fsicontact, build/lib/fsicontact/) and
// an install (P/bin/fsicontact, P/lib/fsicontact/), so that an installed program moved
// anywhere finds its own plugin and never a build tree's (no build path is compiled in).
// A plugin missing or broken is the installation's failure, not the input's: a
// SolverFailure (exit 1), which the callers that make a mesh error an input error
// (a user's .geo or .msh) let through.
#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

#include "mesh/gmsh_model.hpp"
#include "common/errors.hpp"

namespace fsi {
namespace {

constexpr const char* kPluginName = "libfsicontact_gmsh.so";

std::string directory_of(const char* path) {
  char resolved[PATH_MAX];
  if (!path || !::realpath(path, resolved)) return "";
  const std::string p = resolved;
  return p.substr(0, p.find_last_of('/'));
}

// The candidates, first found wins: beside the program's bin/ (../lib/fsicontact/), then
// for the module holding this code: the same, and the Python module's places (it lives
// in build/python/fsicontact/ or P/lib/python3/dist-packages/fsicontact/).
std::vector<std::string> plugin_candidates() {
  std::vector<std::string> dirs;
  if (std::string d = directory_of("/proc/self/exe"); !d.empty()) dirs.push_back(d + "/../lib/fsicontact");
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&plugin_candidates), &info) && info.dli_fname && info.dli_fname[0] == '/')
    if (std::string d = directory_of(info.dli_fname); !d.empty()) {
      dirs.push_back(d + "/../lib/fsicontact");
      dirs.push_back(d + "/../../lib/fsicontact");
      dirs.push_back(d + "/../../../fsicontact");
    }
  std::vector<std::string> out;
  for (const std::string& d : dirs)
    if (std::find(out.begin(), out.end(), d + "/" + kPluginName) == out.end()) out.push_back(d + "/" + kPluginName);
  return out;
}

void* open_plugin(std::string& path) {
  std::string searched;
  for (const std::string& candidate : plugin_candidates()) {
    struct stat st{};
    if (::stat(candidate.c_str(), &st) != 0) {
      searched += (searched.empty() ? "" : ", ") + candidate;
      continue;
    }
    path = candidate;
    if (void* library = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL)) return library;
    const char* why = ::dlerror();
    throw SolverFailure("cannot load the Gmsh plugin " + candidate + ": " + (why ? why : "unknown error") +
                    " (Gmsh itself comes from the Debian package libgmsh-dev)");
  }
  throw SolverFailure(std::string("cannot find the Gmsh plugin ") + kPluginName + " (looked for " + searched +
                  "; rebuild with make program, or reinstall)");
}

const GmshPlugin* load() {
  std::string path;
  void* library = open_plugin(path);
  using Entry = const GmshPlugin* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(library, "fsicontact_gmsh_plugin"));
  const GmshPlugin* plugin = entry ? entry() : nullptr;
  if (!plugin || plugin->version != kGmshPluginVersion)
    throw SolverFailure("the Gmsh plugin " + path + " is of another build (rebuild with make program, or reinstall)");
  if (const std::string error = plugin->initialise(); !error.empty())
    throw SolverFailure("cannot initialise Gmsh: " + error);
  return plugin;  // never unloaded: Gmsh keeps its state for the process
}

}  // namespace

const GmshPlugin& gmsh_plugin() {
  static std::once_flag once;
  static const GmshPlugin* plugin = nullptr;
  std::call_once(once,
                 [] { plugin = load(); });  // a throw leaves the flag unset: the next call retries
  return *plugin;
}

}  // namespace fsi
