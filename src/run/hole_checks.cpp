#include "run/hole_checks.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "mesh/polygon.hpp"
#include "run/point_text.hpp"

namespace fsi {
namespace {

// A hole's edges lie on its obstacle to this fraction of the obstacle's size (r, or a
// polygon's extent), as [obstacle]'s circle is checked (run/mesh_checks.cpp): files
// written with 10 significant digits pass, an obstacle moved by a mesh size fails.
constexpr double kHoleTolerance = 1e-6;

std::string hole_name(std::size_t i) { return "Sigma_5_" + std::to_string(i + 1); }

std::string obstacle_key(std::size_t i) { return "obstacles[" + std::to_string(i + 1) + "]"; }

double size_of(const ObstacleSpec& o) {
  if (o.shape == "disk") return o.r;
  double size = 0;
  for (const Point& p : o.points)
    for (const Point& q : o.points) size = std::max(size, (p - q).norm());
  return size;
}

// How far the edge ab is off the obstacle's boundary: its ends for a circle (a chord's
// middle lies inside by its sagitta), its ends and middle for a polygon (a straight
// edge on one side has all three on it; one cutting a corner does not).
double off_boundary(const ObstacleSpec& o, const Point& a, const Point& b) {
  if (o.shape == "disk") {
    const Point c(o.x0, o.y0);
    return std::max(std::abs((a - c).norm() - o.r), std::abs((b - c).norm() - o.r));
  }
  return std::max({distance_to_boundary(o.points, a), distance_to_boundary(o.points, b),
                   distance_to_boundary(o.points, (a + b) / 2)});
}

bool inside(const ObstacleSpec& o, const Point& x) {
  if (o.shape == "disk") return (x - Point(o.x0, o.y0)).norm() < o.r * (1 - kHoleTolerance);
  return inside_polygon(o.points, x) && distance_to_boundary(o.points, x) > kHoleTolerance * size_of(o);
}

[[noreturn]] void refuse(const Case& c, const std::string& problem, const std::string& allowed) {
  throw InputError(c.source + ": fluid.mesh " + c.fluid->mesh + ": " + problem + "; allowed: " + allowed);
}

const char* kAllowed = "one physical curve per obstacle of [[obstacles]], Sigma_5_1, Sigma_5_2, ... in the case's "
                       "order (Sigma_5 for a single obstacle), on that obstacle's boundary";

void check_hole(const Case& c, const Mesh& mesh, std::size_t i) {
  const ObstacleSpec& o = c.obstacles[i];
  const std::vector<BoundaryEdge> edges = mesh.edges_on(mesh.label(hole_name(i)));
  if (edges.empty())
    refuse(c, "has no hole " + hole_name(i) + " for " + obstacle_key(i) + " (a " + o.shape + ")", kAllowed);
  const double tol = kHoleTolerance * size_of(o);
  for (const BoundaryEdge& e : edges) {
    const Point &a = mesh.vertices[e.v[0]], &b = mesh.vertices[e.v[1]];
    const double off = off_boundary(o, a, b);
    if (!(off <= tol))
      refuse(c,
             "its hole " + hole_name(i) + " has the edge " + point_text(a) + " - " + point_text(b) + ", " +
                 shortest(off) + " off the boundary of " + obstacle_key(i) + " (a " + o.shape + ")",
             std::string(kAllowed) + " within " + shortest(tol));
  }
}

}  // namespace

std::vector<std::string> mesh_hole_groups(const Case& c) {
  if (c.obstacles.size() == 1) return {"Sigma_5", hole_name(0)};
  std::vector<std::string> groups;
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) groups.push_back(hole_name(i));
  return groups;
}

void name_mesh_holes(const Case& c, Mesh& mesh) {
  if (c.obstacles.size() != 1) return;
  const int whole = mesh.label("Sigma_5"), first = mesh.label(hole_name(0));
  if (mesh.edges_on(whole).empty()) return;
  if (!mesh.edges_on(first).empty())
    refuse(c, "names its hole both Sigma_5 and Sigma_5_1", "one of them for a single obstacle");
  for (BoundaryEdge& e : mesh.boundary_edges)
    if (e.label == whole) e.label = first;
}

void check_mesh_holes(const Case& c, const Mesh& mesh) {
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) check_hole(c, mesh, i);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Point g = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0;
    for (std::size_t i = 0; i < c.obstacles.size(); ++i)
      if (inside(c.obstacles[i], g))
        refuse(c, "covers " + obstacle_key(i) + ": its triangle at " + point_text(g) + " lies inside it",
               "D = the box minus every obstacle of [[obstacles]] (each a hole)");
  }
}

}  // namespace fsi
