#include "solid/elasticity.hpp"

#include <vector>

#include "fem/integration.hpp"

namespace fsi {

Lame Lame::from_young_poisson(double E, double nu) {
  return {nu * E / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

SparseMatrix assemble_elasticity(const Mesh& mesh, const Lame& lame) {
  const int nv = mesh.num_vertices();
  return assemble_on_triangles(mesh, 2 * nv, 2 * nv, 36, [&](int t, const P1Triangle& T, const auto& add) {
    const auto& tri = mesh.triangles[t];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            add(dof(tri[a], c, nv), dof(tri[b], d, nv), T.area * elasticity_entry(lame, T.grad.row(a), T.grad.row(b), c, d));
  });
}

SparseMatrix assemble_divergence(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  return assemble_on_triangles(mesh, 2 * nv, nv, 18, [&](int t, const P1Triangle& T, const auto& add) {
    const auto& tri = mesh.triangles[t];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 3; ++k)  // ∫ ∂_c λ_a λ_k = ∂_c λ_a |T|/3
          add(dof(tri[a], c, nv), tri[k], T.grad(a, c) * T.area / 3.0);
  });
}

}  // namespace fsi
