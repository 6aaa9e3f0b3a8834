#include "run/probes.hpp"

#include "fem/point_locator.hpp"

namespace fsi {

Point displacement_at(const Mesh& reference, const Eigen::VectorXd& u, const Point& X) {
  const PointLocator locator(reference);
  const Location at = locator.locate_or_nearest(X);
  const int nv = reference.num_vertices();
  Point d(0, 0);
  for (int a = 0; a < 3; ++a) {
    const int v = reference.triangles[at.triangle][a];
    d += at.lambda[a] * Point(u[v], u[nv + v]);
  }
  return d;
}

Point resultant(const Eigen::VectorXd& load) {
  const Eigen::Index nv = load.size() / 2;
  return load.size() ? Point(load.head(nv).sum(), load.tail(nv).sum()) : Point(0, 0);
}

Point resultant_off(const Eigen::VectorXd& load, const Mesh& mesh, int clamped) {
  const int nv = mesh.num_vertices();
  if (load.size() != 2 * nv) return Point(0, 0);
  std::vector<char> held(nv, 0);
  for (int v : mesh.vertices_on(clamped)) held[v] = 1;
  Point F(0, 0);
  for (int i = 0; i < nv; ++i)
    if (!held[i]) F += Point(load[i], load[nv + i]);
  return F;
}

}  // namespace fsi
