#include "common/plugin_loader.hpp"

#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <vector>

#include "common/errors.hpp"

namespace fsi {
namespace {

std::string directory_of(const char* path) {
  char resolved[PATH_MAX];
  if (!path || !::realpath(path, resolved)) return "";
  const std::string p = resolved;
  return p.substr(0, p.find_last_of('/'));
}

// The candidates, first found wins: beside the program's bin/ (../lib/fsicontact/), then
// for the module holding this code: the same, and the Python module's places (it lives
// in build/python/fsicontact/ or P/lib/python3/dist-packages/fsicontact/).
std::vector<std::string> plugin_candidates(const std::string& file) {
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
    if (std::find(out.begin(), out.end(), d + "/" + file) == out.end()) out.push_back(d + "/" + file);
  return out;
}

}  // namespace

void* open_plugin(const std::string& file, const std::string& what, const std::string& package, std::string& path,
                  bool deep_bind) {
  std::string searched;
  for (const std::string& candidate : plugin_candidates(file)) {
    struct stat st{};
    if (::stat(candidate.c_str(), &st) != 0) {
      searched += (searched.empty() ? "" : ", ") + candidate;
      continue;
    }
    path = candidate;
    if (void* library = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL | (deep_bind ? RTLD_DEEPBIND : 0)))
      return library;
    const char* why = ::dlerror();
    throw SolverFailure("cannot load " + what + " " + candidate + ": " + (why ? why : "unknown error") + " (" +
                        package + ")");
  }
  throw SolverFailure("cannot find " + what + " " + file + " (looked for " + searched + "; " + package +
                      "; rebuild with make program, or reinstall)");
}

void* plugin_symbol(void* library, const char* symbol, const std::string& what, const std::string& path) {
  void* entry = ::dlsym(library, symbol);
  if (!entry) throw SolverFailure(what + " " + path + " has no " + symbol + " (rebuild with make program, or reinstall)");
  return entry;
}

}  // namespace fsi
