#include "fem/p1.hpp"

namespace fsi {

P1Triangle::P1Triangle(const Mesh& mesh, int t)
    : P1Triangle(mesh.vertices[mesh.triangles[t][0]], mesh.vertices[mesh.triangles[t][1]],
                 mesh.vertices[mesh.triangles[t][2]]) {}

P1Triangle::P1Triangle(const Point& a, const Point& b, const Point& c) : x{a, b, c} {
  const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
  area = 0.5 * det;
  // ∇λ_k = rot(x_{k+2} − x_{k+1}) / (2|T|), with signed area.
  for (int k = 0; k < 3; ++k) {
    const Point& p = x[(k + 1) % 3];
    const Point& q = x[(k + 2) % 3];
    grad(k, 0) = (p.y() - q.y()) / det;
    grad(k, 1) = (q.x() - p.x()) / det;
  }
}

Eigen::Vector3d P1Triangle::barycentric(const Point& p) const {
  Eigen::Vector3d l;
  for (int k = 0; k < 3; ++k) l[k] = grad.row(k).dot(p - x[(k + 1) % 3]);
  return l;
}

}  // namespace fsi
