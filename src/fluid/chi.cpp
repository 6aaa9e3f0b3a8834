#include "fluid/chi.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <stdexcept>

#include "fem/p1.hpp"
#include "mesh/clipping.hpp"

namespace fsi {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BgBox = bg::model::box<BgPoint>;

struct ChiComputer::BarycentreIndex {
  bgi::rtree<std::pair<BgPoint, int>, bgi::quadratic<16>> tree;
};

ChiComputer::ChiComputer(const Mesh& fluid_mesh, const PointLocator& fluid_locator, std::string rule)
    : fluid_(fluid_mesh), locator_(fluid_locator), rule_(std::move(rule)),
      barycentres_(std::make_unique<BarycentreIndex>()) {
  if (rule_ != "barycentre" && rule_ != "area-fraction")
    throw std::invalid_argument("unknown chi rule '" + rule_ + "'");
  std::vector<std::pair<BgPoint, int>> points;
  points.reserve(fluid_mesh.triangles.size());
  for (int t = 0; t < fluid_mesh.num_triangles(); ++t) {
    const auto& tri = fluid_mesh.triangles[t];
    const Point g = (fluid_mesh.vertices[tri[0]] + fluid_mesh.vertices[tri[1]] + fluid_mesh.vertices[tri[2]]) / 3.0;
    points.emplace_back(BgPoint(g.x(), g.y()), t);
  }
  barycentres_->tree = decltype(barycentres_->tree)(points.begin(), points.end());
}

ChiComputer::~ChiComputer() = default;

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

// For each structure triangle, the fluid barycentres in its box, tested exactly.
Eigen::VectorXd ChiComputer::barycentre_rule(const Mesh& s) const {
  Eigen::VectorXd chi = Eigen::VectorXd::Zero(fluid_.num_triangles());
  for (int t = 0; t < s.num_triangles(); ++t) {
    Point lo, hi;
    bounding_box(s, t, lo, hi);
    const P1Triangle T(s, t);
    const BgBox box(BgPoint(lo.x(), lo.y()), BgPoint(hi.x(), hi.y()));
    for (auto it = barycentres_->tree.qbegin(bgi::intersects(box)); it != barycentres_->tree.qend(); ++it) {
      const Point g(bg::get<0>(it->first), bg::get<1>(it->first));
      // Closed triangles: a barycentre on a shared edge counts once (χ is 0/1).
      if (T.barycentric(g).minCoeff() >= -1e-14) chi[it->second] = 1.0;
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
