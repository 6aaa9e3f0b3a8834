// libFuzzer target: reading a user's .msh. Gmsh runs in a child process (and is not
// instrumented); what it sends back is built and checked in this process, so the
// fuzzer sees our builder and validation. Contract: any bytes give a MeshError or
// a Mesh that keeps every promise of read_gmsh_file, checked here independently.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include "mesh/gmsh_io.hpp"

namespace {

// Counter-clockwise, positive area; every edge in at most two triangles, traversed
// oppositely; boundary edges on edges of exactly one triangle, each once.
bool keeps_its_promises(const fsi::Mesh& m) {
  const int nv = m.num_vertices();
  std::map<std::pair<int, int>, int> directed;  // (from, to) → uses
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangles[t];
    for (int v : tri)
      if (v < 0 || v >= nv) return false;
    if (!(m.area(t) > 0)) return false;
    for (int k = 0; k < 3; ++k)
      if (++directed[{tri[k], tri[(k + 1) % 3]}] > 1) return false;  // same direction twice
  }
  std::map<std::pair<int, int>, int> boundary;
  for (const auto& e : m.boundary_edges) {
    if (e.label < 0 || e.label >= static_cast<int>(m.label_names.size())) return false;
    for (int v : e.v)
      if (v < 0 || v >= nv) return false;
    const auto key = std::minmax(e.v[0], e.v[1]);
    const int uses =
        directed.count({key.first, key.second}) + directed.count({key.second, key.first});
    if (uses != 1 || ++boundary[key] > 1) return false;
  }
  for (const auto& p : m.vertices)
    if (!p.allFinite()) return false;
  return true;
}

}  // namespace

// Each input forks a child, and fork copies the page tables of the whole resident
// set: with ASan's default 256 MB quarantine resident, 40 inputs/s; with 16 MB, 100
// (measured). The quarantine still outlives every allocation of one input.
extern "C" const char* __asan_default_options() {
  return "quarantine_size_mb=16";
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/fsicontact-fuzz-" + std::to_string(::getpid()) + ".msh";
  static const int cleanup = std::atexit([] { std::remove(path.c_str()); });
  (void)cleanup;
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  // Gmsh reads 20 kB in milliseconds: a stuck child is stopped long before
  // libFuzzer's own time-out would call it a hang.
  const fsi::GmshLimits limits{10};
  try {
    const fsi::Mesh m =
        fsi::read_gmsh_file(path, {"Gamma_D", "Gamma_C", "Gamma_N"}, "Omega_S", limits);
    if (!keeps_its_promises(m)) __builtin_trap();
  } catch (const fsi::MeshError&) {
  }
  return 0;
}
