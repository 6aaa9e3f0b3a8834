#include "fem/point_locator.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/geometries/segment.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <map>
#include <stdexcept>

#include "fem/p1.hpp"

namespace fsi {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BgBox = bg::model::box<BgPoint>;
using BgSegment = bg::model::segment<BgPoint>;

struct PointLocator::Index {
  bgi::rtree<std::pair<BgBox, int>, bgi::quadratic<16>> triangles;
  bgi::rtree<std::pair<BgSegment, int>, bgi::quadratic<16>> boundary;
};

PointLocator::PointLocator(const Mesh& mesh) : mesh_(&mesh), index_(std::make_unique<Index>()) {
  std::vector<std::pair<BgBox, int>> boxes;
  boxes.reserve(mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    Point lo = mesh.vertices[tri[0]], hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = lo.cwiseMin(mesh.vertices[tri[k]]);
      hi = hi.cwiseMax(mesh.vertices[tri[k]]);
    }
    boxes.emplace_back(BgBox(BgPoint(lo.x(), lo.y()), BgPoint(hi.x(), hi.y())), t);
  }
  index_->triangles = decltype(index_->triangles)(boxes.begin(), boxes.end());  // bulk load

  // True boundary: edges used by exactly one triangle (labels may be incomplete).
  std::map<std::pair<int, int>, int> uses;
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<BgSegment, int>> segments;
  int id = 0;
  for (const auto& [edge, count] : uses)
    if (count == 1) {
      const Point& a = mesh.vertices[edge.first];
      const Point& b = mesh.vertices[edge.second];
      segments.emplace_back(BgSegment(BgPoint(a.x(), a.y()), BgPoint(b.x(), b.y())), id++);
    }
  index_->boundary = decltype(index_->boundary)(segments.begin(), segments.end());
}

PointLocator::~PointLocator() = default;
PointLocator::PointLocator(PointLocator&&) noexcept = default;
PointLocator& PointLocator::operator=(PointLocator&&) noexcept = default;

std::optional<Location> PointLocator::locate(const Point& p, double tol) const {
  std::optional<Location> best;
  double best_min = -std::numeric_limits<double>::infinity();
  const BgPoint q(p.x(), p.y());
  for (auto it = index_->triangles.qbegin(bgi::intersects(q)); it != index_->triangles.qend(); ++it) {
    const P1Triangle T(*mesh_, it->second);
    const Eigen::Vector3d l = T.barycentric(p);
    // On a shared edge several triangles qualify: keep the one p is most inside.
    if (l.minCoeff() >= -tol && l.minCoeff() > best_min) {
      best_min = l.minCoeff();
      best = Location{it->second, l};
    }
  }
  return best;
}

Point PointLocator::nearest_boundary_point(const Point& p) const {
  std::vector<std::pair<BgSegment, int>> hit;
  index_->boundary.query(bgi::nearest(BgPoint(p.x(), p.y()), 1), std::back_inserter(hit));
  if (hit.empty()) throw std::logic_error("PointLocator: mesh has no boundary");
  const Point a(bg::get<0, 0>(hit[0].first), bg::get<0, 1>(hit[0].first));
  const Point b(bg::get<1, 0>(hit[0].first), bg::get<1, 1>(hit[0].first));
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return a + t * (b - a);
}

Location PointLocator::locate_or_nearest(const Point& p) const {
  if (!p.allFinite()) throw std::domain_error("cannot locate a point with a non-finite coordinate");
  if (auto loc = locate(p)) return *loc;
  const Point q = nearest_boundary_point(p);
  if (auto loc = locate(q, 1e-9)) {
    loc->lambda = loc->lambda.cwiseMax(0.0);
    loc->lambda /= loc->lambda.sum();  // exactly on the boundary edge
    return *loc;
  }
  // A mesh whose triangles overlap or fold (a structure deformed beyond what it can
  // take, in one fixed-point pass) can leave the nearest boundary point in none of
  // them: the triangle among the nearest few whose coordinates are least negative,
  // clamped onto it (paper-7.2-dynamic.toml to t = 3 s had ended in the exception).
  std::vector<std::pair<BgBox, int>> near;
  index_->triangles.query(bgi::nearest(BgPoint(q.x(), q.y()), 8), std::back_inserter(near));
  std::optional<Location> best;
  for (const auto& [box, t] : near) {
    const Eigen::Vector3d l = P1Triangle(*mesh_, t).barycentric(q);
    if (!best || l.minCoeff() > best->lambda.minCoeff()) best = Location{t, l};
  }
  if (!best) throw std::logic_error("PointLocator: mesh has no triangle");
  best->lambda = best->lambda.cwiseMax(0.0);
  if (!(best->lambda.sum() > 0)) best->lambda.setConstant(1.0 / 3);
  best->lambda /= best->lambda.sum();
  return *best;
}

std::vector<int> PointLocator::triangles_in_box(const Point& lo, const Point& hi) const {
  std::vector<int> out;
  const BgBox box(BgPoint(lo.x(), lo.y()), BgPoint(hi.x(), hi.y()));
  for (auto it = index_->triangles.qbegin(bgi::intersects(box)); it != index_->triangles.qend(); ++it)
    out.push_back(it->second);
  return out;
}

}  // namespace fsi
