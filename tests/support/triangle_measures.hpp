// Measures of a mesh's triangles for the mesh generators' tests.
#pragma once

#include <algorithm>

#include "mesh/mesh.hpp"

namespace fsi::testing {

// The longest of triangle t's three edges.
inline double longest_edge(const Mesh& m, int t) {
  const auto& T = m.triangles[t];
  double e = 0;
  for (int k = 0; k < 3; ++k) e = std::max(e, (m.vertices[T[k]] - m.vertices[T[(k + 1) % 3]]).norm());
  return e;
}

}  // namespace fsi::testing
