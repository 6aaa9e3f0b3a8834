// [[obstacles]] (SPEC §9): disks, polygons and half-planes, any number.
#include <algorithm>
#include <cmath>
#include <string>

#include "io/case.hpp"
#include "io/case_section.hpp"
#include "mesh/polygon.hpp"

namespace fsi::case_detail {
namespace {

constexpr std::size_t kMaxPolygonPoints = 2000;  // the simplicity check is quadratic: 2e6 pairs

// points = [[x, y], ...]: at least three, finite, a simple polygon (no two edges meet
// but neighbours at their shared corner) with an area.
std::vector<Point> read_polygon(Section& s, const std::string& name, const Origin& origin) {
  const std::string key = name + ".points", allowed = "points = [[x, y], ...], at least 3 corners of a simple polygon";
  const toml::array* a = s.array("points");
  if (!a) fail(origin, key, "is missing or not an array", allowed);
  if (a->size() < 3 || a->size() > kMaxPolygonPoints)
    fail(origin, key, "has " + std::to_string(a->size()) + " corners", "3 to " + std::to_string(kMaxPolygonPoints));
  std::vector<Point> p;
  for (const toml::node& n : *a) {
    const toml::array* xy = n.as_array();
    if (!xy || xy->size() != 2 || !(*xy)[0].is_number() || !(*xy)[1].is_number())
      fail(origin, key, "has an entry that is not [x, y]", allowed);
    const Point q(as_double((*xy)[0]), as_double((*xy)[1]));
    if (!kSigned.contains(q.x()) || !kSigned.contains(q.y())) fail(origin, key, "has a corner out of range", kSigned.text());
    p.push_back(q);
  }
  const std::size_t m = p.size();
  if (!(std::abs(signed_area(p)) > 0)) fail(origin, key, "encloses no area", allowed);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      const bool neighbours = j == i + 1 || (i == 0 && j == m - 1);
      if (neighbours ? p[i] == p[(i + 1) % m] || p[j] == p[(j + 1) % m]
                     : segments_cross(p[i], p[(i + 1) % m], p[j], p[(j + 1) % m]))
        fail(origin, key, "is not a simple polygon (its edges " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                              " meet or a corner repeats)", allowed);
    }
  return p;
}

ObstacleSpec read_one(const toml::table* t, const std::string& name, const Origin& origin) {
  Section s(t, name, origin, nullptr);
  ObstacleSpec o;
  o.shape = s.choice("shape", "", {"disk", "polygon", "half-plane"});
  if (o.shape == "polygon") {
    o.points = read_polygon(s, name, origin);
  } else if (o.shape == "disk") {
    o.x0 = s.number("x0", NAN, kSigned);
    o.y0 = s.number("y0", NAN, kSigned);
    o.r = s.number("r", NAN, kSize);
    if (!std::isfinite(o.x0) || !std::isfinite(o.y0) || !std::isfinite(o.r))
      fail(origin, name, "(a disk) needs x0, y0 and r", "shape = \"disk\", x0, y0, r");
  } else {
    o.point = s.vector2("point", Point(NAN, NAN));
    o.normal = s.vector2("normal", Point(NAN, NAN));
    if (!o.point.allFinite() || !o.normal.allFinite())
      fail(origin, name, "(a half-plane) needs point and normal", "shape = \"half-plane\", point = [x, y], normal = [nx, ny]");
    if (!(o.normal.norm() > 0)) fail(origin, name + ".normal", "is zero", "a non-zero vector, pointing out of the obstacle");
    // Kept as given (HalfPlaneObstacle normalises it): normalising here and again when
    // the resolved case.toml is read moved its last bit (fuzz_case's round trip, the
    // capsule case's normal (-0.2, 1)).
  }
  s.reject_unknown();
  return o;
}

}  // namespace

void read_obstacles(const toml::table& root, const Origin& origin, Case& c) {
  const toml::node* n = root.get("obstacles");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a) fail(origin, "obstacles", "must be an array of tables ([[obstacles]])", "[[obstacles]] tables, or [] for none");
  c.obstacles_given = true;
  if (a->size() > 1000) fail(origin, "obstacles", "has " + std::to_string(a->size()) + " entries", "at most 1000");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string name = "obstacles[" + std::to_string(i + 1) + "]";
    const toml::table* t = (*a)[i].as_table();
    if (!t) fail(origin, name, "must be a table", "shape = \"disk\" | \"polygon\" | \"half-plane\" and its keys");
    c.obstacles.push_back(read_one(t, name, origin));
  }
}

}  // namespace fsi::case_detail
