// [[obstacles]] (SPEC §9): disks and half-planes, any number (polygons: not yet).
#include <cmath>
#include <string>

#include "io/case_section.hpp"

namespace fsi::case_detail {
namespace {

ObstacleSpec read_one(const toml::table* t, const std::string& name, const Origin& origin) {
  Section s(t, name, origin, nullptr);
  ObstacleSpec o;
  o.shape = s.text("shape", "");
  if (o.shape == "polygon")  // solid/relinearised_contact.hpp: the iteration cycles at corners
    fail(origin, name + ".shape", "= \"polygon\" is not available yet (the re-linearisation does not settle at its corners)",
         "\"disk\", \"half-plane\"");
  o.shape = s.choice("shape", "", {"disk", "half-plane"});
  if (o.shape == "disk") {
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
    o.normal /= o.normal.norm();
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
