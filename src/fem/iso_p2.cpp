#include "fem/iso_p2.hpp"

#include <Eigen/LU>  // determinant, inverse
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi {

void p2_reference(const Eigen::Vector3d& l, std::array<double, 6>& N, Eigen::Matrix<double, 6, 2>& dN) {
  // ∂λ/∂ξ: λ0 = 1 − ξ1 − ξ2, λ1 = ξ1, λ2 = ξ2.
  const Eigen::Matrix<double, 3, 2> dl = (Eigen::Matrix<double, 3, 2>() << -1, -1, 1, 0, 0, 1).finished();
  for (int a = 0; a < 3; ++a) {
    N[a] = l[a] * (2 * l[a] - 1);
    dN.row(a) = (4 * l[a] - 1) * dl.row(a);
  }
  for (int k = 0; k < 3; ++k) {
    const int m = (k + 1) % 3;
    N[3 + k] = 4 * l[k] * l[m];
    dN.row(3 + k) = 4 * (l[m] * dl.row(k) + l[k] * dl.row(m));
  }
}

IsoP2Geometry::IsoP2Geometry(const P2Space& space, const std::vector<CircleBoundary>& circles, int degree)
    : space_(space), nodes_(space.nodes()) {
  const Mesh& mesh = space.mesh();
  std::vector<char> moved(nodes_.size(), 0);
  for (const CircleBoundary& c : circles)
    for (const BoundaryEdge& e : mesh.edges_on(c.label)) {
      const int m = space.midpoint_of(e);
      const Point d = nodes_[m] - c.centre;
      if (d.norm() == 0) throw std::invalid_argument("IsoP2Geometry: an edge's midpoint at its circle's centre");
      nodes_[m] = c.centre + c.radius * d.normalized();
      moved[m] = 1;
    }
  curved_.assign(mesh.num_triangles(), 0);
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 3; k < 6; ++k) curved_[t] = curved_[t] || moved[space.element(t)[k]];

  const TriangleRule rule = triangle_rule(degree);
  per_triangle_ = static_cast<int>(rule.w.size());
  points_.reserve(static_cast<std::size_t>(per_triangle_) * mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int q = 0; q < per_triangle_; ++q) points_.push_back(point_of(t, rule.lambda[q], rule.w[q]));
}

IsoPoint IsoP2Geometry::point_of(int t, const Eigen::Vector3d& lambda, double weight) const {
  IsoPoint p;
  Eigen::Matrix<double, 6, 2> dN;
  p2_reference(lambda, p.N, dN);
  const std::array<int, 6>& node = space_.element(t);
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(r, s) = ∂x_r/∂ξ_s
  p.x = Point::Zero();
  for (int i = 0; i < 6; ++i) {
    J += nodes_[node[i]] * dN.row(i);
    p.x += p.N[i] * nodes_[node[i]];
  }
  const double det = J.determinant();
  // A curved edge bent so far that the map folds (a triangle thinner than its bulge):
  // the mesh is too coarse at that circle.
  if (!(det > 0))
    throw std::invalid_argument("IsoP2Geometry: triangle " + std::to_string(t) +
                                " folds when its edge is curved onto the circle (refine the mesh at the hole)");
  p.grad = dN * J.inverse();  // ∇_x N = J⁻ᵀ ∇_ξ N, as rows
  p.lambda = lambda;
  p.dx = 0.5 * weight * det;
  return p;
}

int IsoP2Geometry::curved_triangles() const {
  int n = 0;
  for (char c : curved_) n += c;
  return n;
}

double IsoP2Geometry::area() const {
  double a = 0;
  for (const IsoPoint& p : points_) a += p.dx;
  return a;
}

}  // namespace fsi
