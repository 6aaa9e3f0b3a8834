#include "common/plugin_loader.hpp"

#include <dlfcn.h>
#include <malloc.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
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

// A library that a plugin pulls in may set the C allocator's parameters for the whole
// process when it is loaded. SuperLU_DIST (linked by Debian's PETSc, never called here)
// sets M_MMAP_MAX = 0 and M_TRIM_THRESHOLD = -1 in its initialiser: no block is then
// ever mapped on its own nor given back to the system, every large temporary of the
// iterative set-up stays resident once freed, and a run's later passes peaked higher
// and higher, by how much varying from run to run, as a set-up's blocks fitted the holes
// the last one left or not (docs/performance.md, "The run's later passes"). Where a
// plugin did that, they are set back: blocks of 1 MiB or more mapped on their own and
// given back when freed. That costs time, each set-up's pages faulted in anew: 1 MiB
// peaked as low as 128 KiB (1 034 and 1 032 MB over three passes at 930 k triangles,
// against 1 270–1 285) for 11 % more time, 32 MiB (glibc's own largest) 1 132 MB for 8 %.
constexpr int kMmapThreshold = 1 << 20;

// Whether the allocator maps a large block on its own: one of 64 MiB, above any
// threshold glibc would choose itself, is, unless mapping was turned off.
bool maps_large_blocks() {
  const std::size_t before = ::mallinfo2().hblks;
  void* block = std::malloc(std::size_t{64} << 20);
  const bool mapped = ::mallinfo2().hblks > before;
  std::free(block);
  return mapped;
}

void restore_allocator() {
  if (maps_large_blocks()) return;
  ::mallopt(M_MMAP_MAX, 65536);  // glibc's default
  ::mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  ::mallopt(M_TRIM_THRESHOLD, 2 * kMmapThreshold);  // glibc's rule: twice the mmap threshold
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
    if (void* library = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL | (deep_bind ? RTLD_DEEPBIND : 0))) {
      restore_allocator();
      return library;
    }
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
