#include "fem/probes.hpp"

#include "fem/point_locator.hpp"

namespace fsi {

namespace {

// The P2 interpolant of u at a point located in p2's element mesh.
Point interpolate(const P2Space& p2, const Eigen::VectorXd& u, const Location& at) {
  const P2Values v = p2_values(P1Triangle(p2.mesh(), at.triangle), at.lambda);
  return p2_vector_at(p2.element(at.triangle), v, u, p2.num_nodes()).value;
}

// The P1 interpolant of u at a located point (or P2's, with p2).
Point interpolate(const Mesh& reference, const Eigen::VectorXd& u, const Location& at, const P2Space* p2) {
  if (p2) return interpolate(*p2, u, at);
  const int nv = reference.num_vertices();
  Point d(0, 0);
  for (int a = 0; a < 3; ++a) {
    const int v = reference.triangles[at.triangle][a];
    d += at.lambda[a] * Point(u[v], u[nv + v]);
  }
  return d;
}

}  // namespace

Point displacement_at(const Mesh& reference, const Eigen::VectorXd& u, const Point& X, const P2Space* p2) {
  return interpolate(reference, u, PointLocator(p2 ? p2->mesh() : reference).locate_or_nearest(X), p2);
}

ProbeSet::ProbeSet(const Mesh& reference, const std::vector<Point>& points, const P2Space* p2)
    : reference_(reference), p2_(p2) {
  if (points.empty()) return;
  const PointLocator locator(p2 ? p2->mesh() : reference);
  for (const Point& X : points) at_.push_back(locator.locate_or_nearest(X));
}

std::vector<Point> ProbeSet::displacements(const Eigen::VectorXd& u) const {
  std::vector<Point> d;
  for (const Location& at : at_) d.push_back(interpolate(reference_, u, at, p2_));
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
