// libFuzzer target: reading a user's .msh (our wrapper over the Gmsh SDK's reader).
// Contract: any bytes give a Mesh or a MeshError. Gmsh is not instrumented, so its
// parser is exercised by mutation without coverage feedback.
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "mesh/gmsh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/fsicontact-fuzz-" + std::to_string(::getpid()) + ".msh";
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const fsi::Mesh m = fsi::read_gmsh_file(path, {"Gamma_D", "Gamma_C", "Gamma_N"}, "Omega_S");
    for (const auto& t : m.triangles)  // the mesh handed on must be usable
      for (int v : t)
        if (v < 0 || v >= m.num_vertices()) __builtin_trap();
  } catch (const fsi::MeshError&) {
  }
  return 0;
}
