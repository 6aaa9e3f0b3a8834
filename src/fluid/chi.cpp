#include "fluid/chi.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/p1.hpp"
#include "mesh/clipping.hpp"

namespace fsi {

ChiComputer::ChiComputer(const Mesh& fluid_mesh, const PointLocator& fluid_locator, std::string rule)
    : fluid_(fluid_mesh), locator_(fluid_locator), rule_(std::move(rule)) {
  if (rule_ != "barycentre" && rule_ != "area-fraction")
    throw std::invalid_argument("unknown chi rule '" + rule_ + "'");
}

Eigen::VectorXd ChiComputer::operator()(const Mesh& s) const {
  return rule_ == "barycentre" ? barycentre_rule(s) : area_fraction_rule(s);
}

namespace {
void bounding_box(const Mesh& m, int t, Point& lo, Point& hi) {
  const auto& tri = m.triangles[t];
  lo = hi = m.vertices[tri[0]];
  for (int k = 1; k < 3; ++k) {
    lo = lo.cwiseMin(m.vertices[tri[k]]);
    hi = hi.cwiseMax(m.vertices[tri[k]]);
  }
}
}  // namespace

// For each structure triangle, the barycentres of the fluid triangles whose boxes meet
// its box (the locator's index: a barycentre in the box has its triangle's box meeting
// it), tested exactly. An index of the barycentres of its own would cost 46 bytes a
// fluid triangle (issue 32's memory budget) for fewer candidates near the box's edges.
Eigen::VectorXd ChiComputer::barycentre_rule(const Mesh& s) const {
  Eigen::VectorXd chi = Eigen::VectorXd::Zero(fluid_.num_triangles());
  for (int t = 0; t < s.num_triangles(); ++t) {
    Point lo, hi;
    bounding_box(s, t, lo, hi);
    const P1Triangle T(s, t);
    for (int f : locator_.triangles_in_box(lo, hi)) {
      const auto& tri = fluid_.triangles[f];
      const Point g = (fluid_.vertices[tri[0]] + fluid_.vertices[tri[1]] + fluid_.vertices[tri[2]]) / 3.0;
      if (g.x() < lo.x() || g.x() > hi.x() || g.y() < lo.y() || g.y() > hi.y()) continue;
      // Closed triangles: a barycentre on a shared edge counts once (χ is 0/1).
      if (T.barycentric(g).minCoeff() >= -1e-14) chi[f] = 1.0;
    }
  }
  return chi;
}

Eigen::VectorXd ChiComputer::area_fraction_rule(const Mesh& s) const {
  Eigen::VectorXd covered = Eigen::VectorXd::Zero(fluid_.num_triangles());
  for (int t = 0; t < s.num_triangles(); ++t) {
    Point lo, hi;
    bounding_box(s, t, lo, hi);
    const auto& st = s.triangles[t];
    const std::array<Point, 3> a{s.vertices[st[0]], s.vertices[st[1]], s.vertices[st[2]]};
    for (int f : locator_.triangles_in_box(lo, hi)) {
      const auto& ft = fluid_.triangles[f];
      covered[f] += triangle_intersection_area(a, {fluid_.vertices[ft[0]], fluid_.vertices[ft[1]], fluid_.vertices[ft[2]]});
    }
  }
  Eigen::VectorXd chi(fluid_.num_triangles());
  for (int f = 0; f < fluid_.num_triangles(); ++f) chi[f] = std::clamp(covered[f] / fluid_.area(f), 0.0, 1.0);
  return chi;
}

}  // namespace fsi
