#include "run/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "fem/point_locator.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/case_contact.hpp"
#include "run/hole_checks.hpp"
#include "run/point_text.hpp"
#include "solid/obstacle.hpp"

namespace fsi {
namespace {

// Coordinates of two descriptions of one point agree to this fraction of the
// domain's size: files written with 10 significant digits pass, a wrong key fails.
constexpr double kRelativeTolerance = 1e-8;

std::string at(const Point& p) { return point_text(p); }

struct Box {
  Point lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
};

Box bounding_box(const Mesh& mesh) {
  Box b;
  for (const Point& p : mesh.vertices) b.lo = b.lo.cwiseMin(p), b.hi = b.hi.cwiseMax(p);
  return b;
}

// x strictly inside the counter-clockwise triangle abc.
// x in the closed triangle abc (counter-clockwise): on no side's right.
bool in_closed_triangle(const Point& a, const Point& b, const Point& c, const Point& x) {
  auto not_right = [&x](const Point& p, const Point& q) {
    return (q - p).x() * (x - p).y() - (q - p).y() * (x - p).x() >= 0;
  };
  return not_right(a, b) && not_right(b, c) && not_right(c, a);
}

// x inside the structure: in a triangle, or on an edge or a vertex between triangles,
// but not on the boundary (touching it is allowed).
bool inside_mesh(const Mesh& mesh, const Point& x) {
  for (const BoundaryEdge& e : mesh.boundary_edges) {
    const Point &a = mesh.vertices[e.v[0]], &b = mesh.vertices[e.v[1]];
    const double cross = (b - a).x() * (x - a).y() - (b - a).y() * (x - a).x();
    if (cross == 0 && (x - a).dot(b - a) >= 0 && (x - b).dot(a - b) >= 0) return false;
  }
  for (const auto& t : mesh.triangles)
    if (in_closed_triangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], x))
      return true;
  return false;
}

// The open segments ab and cd cross at one point inside both (touching is not crossing).
bool strictly_crossing(const Point& a, const Point& b, const Point& c, const Point& d) {
  auto side = [](const Point& p, const Point& q, const Point& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

// "<case>: <key> = <value> contradicts <what> <file>: <detail>; allowed: <allowed>"
[[noreturn]] void contradiction(const Case& c, const std::string& key, double value, const std::string& what,
                                const std::string& file, const std::string& detail, const std::string& allowed) {
  throw InputError(c.source + ": " + key + " = " + shortest(value) + " contradicts " + what + " " + file + ": " +
                   detail + "; allowed: " + allowed);
}

void check_labelled(const Case& c, const Mesh& mesh, const std::string& what) {
  const auto [a, b] = unlabelled_boundary_edge(mesh);
  if (a >= 0)
    throw InputError(c.source + ": " + what + ": the boundary edge " + at(mesh.vertices[a]) + " - " +
                     at(mesh.vertices[b]) + " belongs to no boundary part; allowed: every boundary edge in one "
                     "physical curve (its condition would be silently traction-free)");
}

void check_extent(const Case& c, const Mesh& mesh) {
  const Box b = bounding_box(mesh);
  const auto& s = c.structure;
  const double tol = kRelativeTolerance * std::hypot(s.L, s.H);
  const std::string file = s.file(), key = "structure." + s.shape;
  if (std::abs(b.lo.x()) > tol || std::abs(b.lo.y()) > tol)
    throw InputError(c.source + ": " + key + " " + file + " starts at " + at(b.lo) +
                     "; allowed: the reference configuration (0, L) x (0, H), its lower left corner at (0, 0)");
  if (std::abs(b.hi.x() - s.L) > tol)
    contradiction(c, "structure.L", s.L, key, file, "its vertices reach x = " + shortest(b.hi.x()),
                  "structure.L = " + shortest(b.hi.x()) + ", the mesh's length");
  if (std::abs(b.hi.y() - s.H) > tol)
    contradiction(c, "structure.H", s.H, key, file, "its vertices reach y = " + shortest(b.hi.y()),
                  "structure.H = " + shortest(b.hi.y()) + ", the mesh's thickness");
}

void check_contact_zone(const Case& c, const Mesh& mesh, const std::string& what) {
  const auto& o = c.obstacle;
  const DiskFoundation psi(o.x0, o.y0, o.r);
  const std::vector<int> zone = mesh.vertices_on(mesh.label("Gamma_C"));
  for (int v : zone)
    if (!psi.defined_at(mesh.vertices[v].x()))
      throw InputError(c.source + ": " + what + ": Gamma_C reaches x = " + shortest(mesh.vertices[v].x()) +
                       ", outside the obstacle's span; allowed: (x0 - r, x0 + r) = (" + shortest(o.x0 - o.r) + ", " +
                       shortest(o.x0 + o.r) + ")");
  // One contact row per vertex strictly inside Γ_C (SPEC §2): its ends are the
  // vertices of Γ_C met by one Γ_C edge only.
  std::map<int, int> uses;
  for (const auto& e : mesh.edges_on(mesh.label("Gamma_C"))) ++uses[e.v[0]], ++uses[e.v[1]];
  const bool interior = std::any_of(uses.begin(), uses.end(), [](const auto& u) { return u.second >= 2; });
  if (!interior)
    throw InputError(c.source + ": " + what + ": Gamma_C has no vertex strictly inside it, so no contact can be "
                     "imposed; allowed: Gamma_C longer than the mesh size (2 * obstacle.gamma * obstacle.r = " +
                     shortest(2 * o.gamma * o.r) + " > structure.h = " + shortest(c.structure.h) + ")");
}

// A part of the structure that no path of triangles joins to Γ_D floats: nothing
// holds it but frictionless contact, A_S is singular and the Cholesky factorisation
// fails (a solver error for what is an input error).
void check_clamped(const Case& c, const Mesh& mesh, const std::string& what) {
  std::vector<int> parent(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v) parent[v] = v;
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles) parent[root(t[1])] = root(t[0]), parent[root(t[2])] = root(t[0]);
  std::vector<char> held(mesh.num_vertices(), 0);
  for (int v : mesh.vertices_on(mesh.label("Gamma_D"))) held[root(v)] = 1;
  for (const auto& t : mesh.triangles)
    if (!held[root(t[0])])
      throw InputError(c.source + ": " + what + ": the part of the structure around " + at(mesh.vertices[t[0]]) +
                       " is not connected to Gamma_D; allowed: every part of the mesh joined to the clamped side");
}

// A polygon can reach into the structure between its vertices (a wedge's tip into a
// beam's side, a thin bar across it): the vertices' gaps do not see it. Touching (a
// side along the structure's boundary) is allowed, as the gap's margin allows it.
void check_corners_outside(const Case& c, const Mesh& mesh, const std::string& what) {
  const std::string allowed = "; allowed: every obstacle outside the structure's initial configuration";
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) {
    const std::vector<Point>& p = c.obstacles[i].points;
    const std::string whose = " of obstacles[" + std::to_string(i + 1) + "]";
    for (const Point& corner : p)
      if (inside_mesh(mesh, corner))
        throw InputError(c.source + ": " + what + ": the corner " + at(corner) + whose +
                         " lies inside the structure at rest" + allowed);
    for (std::size_t k = 0; k < p.size(); ++k)
      for (const BoundaryEdge& e : mesh.boundary_edges)
        if (strictly_crossing(p[k], p[(k + 1) % p.size()], mesh.vertices[e.v[0]], mesh.vertices[e.v[1]]))
          throw InputError(c.source + ": " + what + ": the side " + at(p[k]) + " - " + at(p[(k + 1) % p.size()]) +
                           whose + " crosses the structure's boundary at rest" + allowed);
  }
}

void check_outside_disk(const Case& c, const Mesh& mesh, const std::string& what) {
  if (c.obstacles_given) {  // [[obstacles]]: every vertex outside every obstacle
    const ContactGap gap = case_contact_gap(c, mesh);
    const double d = gap.min_gap(mesh, Eigen::VectorXd::Zero(2 * mesh.num_vertices()), /*all_vertices=*/true);
    // Within kPolygonMargin · diam counts as touching, not inside: a polygon is grown by it.
    if (d < -kPolygonMargin * diameter(mesh) * (1 + 1e-9))
      throw InputError(c.source + ": " + what + ": the structure starts inside an obstacle of [[obstacles]] (by " +
                       shortest(-d) + " m); allowed: every vertex outside every obstacle");
    check_corners_outside(c, mesh, what);
    return;
  }
  const auto& o = c.obstacle;
  for (const Point& X : mesh.vertices)
    if ((X - Point(o.x0, o.y0)).norm() < o.r)
      throw InputError(c.source + ": " + what + ": the structure starts inside the obstacle (vertex " + at(X) +
                       "); allowed: every vertex outside the disk");
}

void check_inside_box(const Case& c, const Mesh& mesh, const std::string& what) {
  const auto& f = *c.fluid;
  const Box b = bounding_box(mesh);
  const double tol = kRelativeTolerance * std::hypot(f.L1, f.H1 + f.H2);
  if (b.lo.x() < -tol || b.hi.x() > f.L1 + tol || b.lo.y() < -f.H2 - tol || b.hi.y() > f.H1 + tol)
    throw InputError(c.source + ": " + what + ": the structure spans " + at(b.lo) + " - " + at(b.hi) +
                     ", outside the fluid box (0, fluid.L1) x (-fluid.H2, fluid.H1) = (0, " + shortest(f.L1) +
                     ") x (" + shortest(-f.H2) + ", " + shortest(f.H1) + "); allowed: a structure inside the box");
}

// An inflow on Σ1 would blow into the structure's clamped side Γ_D where it lies on
// x = 0: the inflow's velocity prescribed at fluid vertices the structure covers,
// against the penalty that holds v ≈ 0 there (SPEC §1: Γ_D lies on Σ1).
void check_clamp_off_inflow(const Case& c, const Mesh& mesh, const std::string& what) {
  if (!c.fluid || c.fluid->sides[0] != "inflow") return;
  const double tol = kRelativeTolerance * std::hypot(c.fluid->L1, c.fluid->H1 + c.fluid->H2);
  for (int v : mesh.vertices_on(mesh.label("Gamma_D")))
    if (std::abs(mesh.vertices[v].x()) <= tol)
      throw InputError(c.source + ": fluid.left = \"inflow\" blows into the structure's clamped side Gamma_D on " +
                       "Sigma_1 (" + what + ", vertex " + at(mesh.vertices[v]) + "); allowed: fluid.left = " +
                       "\"wall\" or \"outflow\" while the structure is clamped on x = 0");
}

// [obstacle]'s disk is the file's hole Sigma_5: its vertices on the circle, no triangle inside.
void check_disk_hole(const Case& c, const Mesh& mesh) {
  const auto& o = c.obstacle;
  const std::string file = c.fluid->mesh;
  const Point centre(o.x0, o.y0);
  for (int v : mesh.vertices_on(mesh.label("Sigma_5"))) {
    const double d = (mesh.vertices[v] - centre).norm();
    if (std::abs(d - o.r) > 1e-6 * o.r)
      contradiction(c, "obstacle.r", o.r, "fluid.mesh", file,
                    "its Sigma_5 vertex " + at(mesh.vertices[v]) + " lies " + shortest(d) + " from the centre (" +
                        shortest(o.x0) + ", " + shortest(o.y0) + ")",
                    "obstacle.x0, y0, r describing the hole Sigma_5 of the mesh");
  }
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Point g = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0;
    if ((g - centre).norm() < o.r * (1 - 1e-6))
      throw InputError(c.source + ": fluid.mesh " + file + " covers the obstacle: its triangle at " + at(g) +
                       " lies inside the disk; allowed: D = the box minus the disk (obstacle.x0, y0, r)");
  }
}

}  // namespace

Mesh read_case_mesh(const Case& c, const std::string& key, const std::string& path,
                    const std::vector<std::string>& curves, const std::string& surface, double max_triangles,
                    const std::vector<std::string>& optional_curves) {
  Mesh mesh;
  try {
    mesh = read_gmsh_file(path, curves, surface, {}, optional_curves);
  } catch (const MeshError& e) {
    throw InputError(c.source + ": " + key + ": " + e.what());
  }
  if (mesh.num_triangles() > max_triangles)
    throw InputError(c.source + ": " + key + ": " + path + " has " + std::to_string(mesh.num_triangles()) +
                     " triangles; allowed: at most " + std::to_string(static_cast<long>(max_triangles)));
  return mesh;
}

std::array<int, 2> unlabelled_boundary_edge(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& e : mesh.boundary_edges) uses.erase(std::minmax(e.v[0], e.v[1]));
  for (const auto& [edge, n] : uses)
    if (n == 1) return {edge.first, edge.second};
  return {-1, -1};
}

// A file's structure: the strain of its loads (its diameter known now), and the
// candidate edges contact.boundary = "Gamma_C" asks for.
void check_file_structure(const Case& c, const Mesh& mesh, const std::string& what) {
  const Box b = bounding_box(mesh);
  const std::string problem = load_strain_problem(c, (b.hi - b.lo).norm());
  if (!problem.empty()) throw InputError(c.source + ": " + what + ": " + problem);
  if (c.contact.boundary == "Gamma_C" && mesh.edges_on(mesh.label("Gamma_C")).empty())
    throw InputError(c.source + ": " + what + " has no physical curve Gamma_C, the candidate edges of contact.boundary = "
                     "\"Gamma_C\"; allowed: a physical curve Gamma_C, or contact.boundary = \"all\" (with contact.gap = \"normal\")");
}

// output.probes (SPEC §11) are material points: each in Ω_S0, up to 1e-9 of its
// diameter (a point on the boundary written with a rounded last digit passes).
namespace {

// The first of `points` farther than `tol` from `mesh` (its index and that distance).
std::optional<std::pair<std::size_t, double>> first_point_outside(const Mesh& mesh, const std::vector<Point>& points,
                                                                  double tol) {
  const PointLocator locator(mesh);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& x = points[i];
    const double distance = locator.locate(x) ? 0.0 : (locator.nearest_boundary_point(x) - x).norm();
    if (distance > tol) return std::make_pair(i, distance);
  }
  return std::nullopt;
}

}  // namespace

void check_probes_inside(const Case& c, const Mesh& mesh, const std::string& what) {
  if (c.output.probes.empty()) return;
  const Box b = bounding_box(mesh);
  const double tol = 1e-9 * (b.hi - b.lo).norm();
  if (const auto out = first_point_outside(mesh, c.output.probes, tol))
    throw InputError(c.source + ": output.probes[" + std::to_string(out->first + 1) + "] = " +
                     at(c.output.probes[out->first]) + " is " + approx(out->second) + " m outside the structure (" +
                     what + "); allowed: points of the reference configuration, within " + approx(tol) + " m of it");
}

// output.fluid_probes (SPEC §10) lie in D: inside the mesh, or within a tenth of hF of
// it (a point on a curved hole's boundary falls just off the meshed polygon; it is read
// at the nearest boundary point).
void check_fluid_probes_inside(const Case& c, const Mesh& mesh) {
  if (c.output.fluid_probes.empty()) return;
  const double tol = 0.1 * c.fluid->h;
  if (const auto out = first_point_outside(mesh, c.output.fluid_probes, tol))
    throw InputError(c.source + ": output.fluid_probes[" + std::to_string(out->first + 1) + "] = " +
                     at(c.output.fluid_probes[out->first]) + " is " + approx(out->second) +
                     " m outside the fluid domain (a hole or beyond the box); allowed: points of the fluid's mesh, "
                     "within fluid.h / 10 = " + approx(tol) + " m of it");
}

void check_structure_mesh(const Case& c, const Mesh& mesh) {
  const auto& s = c.structure;
  const std::string what = s.rectangle() ? "the generated structure mesh" : "structure." + s.shape + " " + s.file();
  if (!s.rectangle()) {
    if (s.extent_given) check_extent(c, mesh);
    check_labelled(c, mesh, what);
    check_file_structure(c, mesh, what);
  }
  if (c.contact.gap == "paper") check_contact_zone(c, mesh, what);  // ψ's span; "normal" needs none
  if (c.structure.clamped) check_clamped(c, mesh, what);  // a free body (SPEC §12) has no Γ_D
  check_outside_disk(c, mesh, what);
  if (c.fluid) check_inside_box(c, mesh, what);
  check_clamp_off_inflow(c, mesh, what);
  check_probes_inside(c, mesh, what);
}

void check_fluid_mesh(const Case& c, const Mesh& mesh) {
  const auto& f = *c.fluid;
  const std::string file = f.mesh;
  const double tol = kRelativeTolerance * std::hypot(f.L1, f.H1 + f.H2);
  const Box b = bounding_box(mesh);
  if (std::abs(b.lo.x()) > tol)
    throw InputError(c.source + ": fluid.mesh " + file + " starts at x = " + shortest(b.lo.x()) +
                     "; allowed: the box (0, L1) x (-H2, H1), its left side Sigma_1 on x = 0");
  if (std::abs(b.hi.x() - f.L1) > tol)
    contradiction(c, "fluid.L1", f.L1, "fluid.mesh", file, "its vertices reach x = " + shortest(b.hi.x()),
                  "fluid.L1 = " + shortest(b.hi.x()) + ", the mesh's");
  if (std::abs(b.hi.y() - f.H1) > tol)
    contradiction(c, "fluid.H1", f.H1, "fluid.mesh", file, "its vertices reach y = " + shortest(b.hi.y()),
                  "fluid.H1 = " + shortest(b.hi.y()) + ", the mesh's");
  if (std::abs(b.lo.y() + f.H2) > tol)
    contradiction(c, "fluid.H2", f.H2, "fluid.mesh", file, "its vertices reach y = " + shortest(b.lo.y()),
                  "fluid.H2 = " + shortest(-b.lo.y()) + ", the mesh's");
  // Each side's label on that side: its condition (fluid.left, ...) goes where Sigma_k is.
  const struct {
    int k;  // Σ(k+1)
    const char* side;
    int axis;
    double value;
  } sides[] = {{3, "the top y = fluid.H1", 1, f.H1},
               {0, "the left side x = 0", 0, 0.0},
               {1, "the bottom y = -fluid.H2", 1, -f.H2},
               {2, "the right side x = fluid.L1", 0, f.L1}};
  for (const auto& side : sides) {
    const std::string label = "Sigma_" + std::to_string(side.k + 1);
    const std::string where = std::string(side.side) + " (fluid." + kBoxSideKeys[side.k] + " = \"" + f.sides[side.k] + "\")";
    for (int v : mesh.vertices_on(mesh.label(label)))
      if (std::abs(mesh.vertices[v][side.axis] - side.value) > tol)
        throw InputError(c.source + ": fluid.mesh " + file + ": " + label + " has the vertex " +
                         at(mesh.vertices[v]) + ", not on " + where + "; allowed: " + label + " = " + where);
  }
  if (c.obstacles_given)
    check_mesh_holes(c, mesh);  // a hole per obstacle (run/hole_checks.hpp)
  else
    check_disk_hole(c, mesh);
  check_labelled(c, mesh, "fluid.mesh " + file);
}

}  // namespace fsi
