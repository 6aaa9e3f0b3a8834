// Structured triangulations for tests: (0,L)×(0,H) split into nx×ny rectangles,
// each cut along a diagonal; boundary labels "left", "right", "bottom", "top".
// With `union_jack`, each rectangle is cut into four triangles by its centre: every
// cell is identical and mirror-symmetric, so x-invariant data give x-invariant
// discrete solutions exactly.
#pragma once

#include "mesh/mesh.hpp"

namespace fsi::testing {

inline Mesh structured_rectangle(double L, double H, int nx, int ny, bool union_jack = false) {
  Mesh m;
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.vertices.emplace_back(L * i / nx, H * j / ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (union_jack) {
        const int c = m.num_vertices();
        m.vertices.emplace_back(L * (i + 0.5) / nx, H * (j + 0.5) / ny);
        m.triangles.push_back({id(i, j), id(i + 1, j), c});
        m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), c});
        m.triangles.push_back({id(i + 1, j + 1), id(i, j + 1), c});
        m.triangles.push_back({id(i, j + 1), id(i, j), c});
      } else {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  const int left = m.add_label("left"), right = m.add_label("right"),
            bottom = m.add_label("bottom"), top = m.add_label("top");
  for (int i = 0; i < nx; ++i) {
    m.boundary_edges.push_back({{id(i, 0), id(i + 1, 0)}, bottom});
    m.boundary_edges.push_back({{id(i + 1, ny), id(i, ny)}, top});
  }
  for (int j = 0; j < ny; ++j) {
    m.boundary_edges.push_back({{id(0, j + 1), id(0, j)}, left});
    m.boundary_edges.push_back({{id(nx, j), id(nx, j + 1)}, right});
  }
  return m;
}

}  // namespace fsi::testing
