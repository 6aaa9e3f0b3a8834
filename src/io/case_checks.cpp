// The checks that involve several keys: the geometry must be meshable at the sizes
// asked for, the problem must fit the stated limits, and the loads must give
// numbers a double can hold. Each names the key to change and the allowed range.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "io/case_reader.hpp"
#include "mesh/mesh_geometry.hpp"  // kBandGrowth, hole_perimeter
#include "mesh/polygon.hpp"

namespace fsi::case_detail {
namespace {

// Strains above this are not small by any reading, and far below any overflow
// (displacements scale as strain · diam · (L/H)², inside 1e±30 · 1e6 · 1e10).
constexpr double kMaxStrainScale = 1e6;

// Distance from a point to the rectangle [0,L]×[0,H].
double distance_to_rectangle(double x, double y, double L, double H) {
  const double dx = std::max({0.0 - x, 0.0, x - L}), dy = std::max({0.0 - y, 0.0, y - H});
  return std::hypot(dx, dy);
}

// The ends of Γ_C split the bottom side; Gmsh does not refine next to a short piece,
// so it leaves a sliver whose smallest angle falls with the piece's length d
// (measured, hS = 1.5e-3: 6.8° at d = hS/10, 0.69° at hS/100, 0 at 1.5e-12, and
// 6e-16 gave a zero-area triangle). A twentieth of hS keeps every angle above ~3°.
void check_contact_zone(const Case& c, const Origin& o) {
  const auto& s = c.structure;
  const auto& ob = c.obstacle;
  const double piece = s.h / 20;
  // A contact row sits at a vertex strictly inside Γ_C (SPEC §2): Γ_C = 2·gamma·r must
  // be longer than a mesh edge (and a tiny one, below the coordinates' round-off, is
  // no boundary piece at all for the mesher).
  if (!(2 * ob.gamma * ob.r > s.h))
    fail(o, "obstacle.gamma", "= " + shortest(ob.gamma) + " makes Gamma_C (2 * gamma * r = " + approx(2 * ob.gamma * ob.r) +
             ") no longer than a mesh edge (structure.h = " + shortest(s.h) + "): no vertex inside it, no contact row",
         "gamma > structure.h / (2 r) = " + approx(s.h / (2 * ob.r)) + " and < 1, or a smaller structure.h");
  const std::string zone = "Gamma_C = (" + approx(ob.xc_min(), 6) + ", " + approx(ob.xc_max(), 6) + ")";
  if (!(ob.xc_min() >= piece))
    fail(o, "obstacle.x0", "puts " + zone + " only " + approx(ob.xc_min()) + " from the structure's clamped end x = 0",
         "x0 - gamma*r >= structure.h/20 = " + approx(piece) + " (" + o.value("structure.h", s.h, "obstacle.x0") +
             "), or a smaller structure.h");
  if (!(s.L - ob.xc_max() >= piece))
    fail(o, "obstacle.x0", "puts " + zone + " only " + approx(s.L - ob.xc_max()) + " from the structure's end x = L",
         "x0 + gamma*r <= structure.L - structure.h/20 = " + approx(s.L - piece, 6) + " (" +
             o.value("structure.L", s.L, "obstacle.x0") + ", " + o.value("structure.h", s.h, "obstacle.x0") +
             "), or a smaller structure.h");
}

void check_structure_mesh_size(const Case& c, const Origin& o) {
  const auto& s = c.structure;
  if (!(s.h <= s.L / 2))
    fail(o, "structure.h", "= " + shortest(s.h) + " is more than half the structure's length",
         "(0, structure.L/2 = " + shortest(s.L / 2) + "] (" + o.value("structure.L", s.L, "structure.h") + ")");
  // Triangles ten times longer than thick still have angles of ~6°; beyond, Gmsh
  // fails outright (H = 1e-12 with hS = 1.35e-3 aborted inside its meshing).
  if (!(s.h <= 10 * s.H))
    fail(o, "structure.h", "= " + shortest(s.h) + " is more than ten times the structure's thickness",
         "(0, 10 * structure.H = " + shortest(10 * s.H) + "] (" + o.value("structure.H", s.H, "structure.h") + ")");
  // P2 has four times P1's nodes on the same mesh: its limit is a quarter of the triangles.
  const double per = s.element == "P2" ? 4 : 1, limit = case_limits().structure_triangles / per;
  const double estimate = std::max(2.4 * s.L * s.H / (s.h * s.h), 2.0 * s.L / s.h);
  if (estimate > limit)
    fail(o, "structure.h", "= " + shortest(s.h) + " would need about " + approx(estimate) +
                               " triangles for structure.L x structure.H = " + shortest(s.L) + " x " + shortest(s.H) +
                               ", above the limit of " + shortest(limit) + (per > 1 ? " for P2 elements" : ""),
         ">= " + approx(std::sqrt(2.4 * s.L * s.H / limit)) + " for this structure");
}

void check_rectangle_against_obstacle(const Case& c, const Origin& o) {
  const auto& s = c.structure;
  const auto& ob = c.obstacle;
  if (distance_to_rectangle(ob.x0, ob.y0, s.L, s.H) < ob.r || ob.y0 + ob.r > 0)
    fail(o, "obstacle.y0", "= " + shortest(ob.y0) + " puts the structure inside the obstacle at rest",
         "y0 + r <= 0 (the disk's top below the structure's bottom y = 0)");
}

// The rectangle's: the strain check of load_strain_problem with its diameter.
void check_strain(const Case& c, const Origin& o) {
  const std::string problem = load_strain_problem(c, std::hypot(c.structure.L, c.structure.H));
  if (!problem.empty()) throw InputError(o.of("structure.E") + ": " + problem);
}

// A hole of the generated box: [obstacle]'s disk, or a disk or polygon (`corners`) of
// [[obstacles]]; `key` names it in messages ("obstacle", "obstacles[2]").
struct Hole {
  double x0, y0, r;
  std::vector<Point> corners;
  std::string key;
  bool polygon() const { return !corners.empty(); }
  double area() const { return polygon() ? std::abs(signed_area(corners)) : std::numbers::pi * r * r; }
  double perimeter() const { return hole_perimeter(r, corners); }
  // The key whose value places it, and where it is, for messages.
  std::string place_key() const { return key + (polygon() ? ".points" : ".r"); }
  std::string where() const {
    return polygon() ? "" : "= " + shortest(r) + " at (" + shortest(x0) + ", " + shortest(y0) + ") ";
  }
};

std::vector<Hole> fluid_holes(const Case& c) {
  if (!c.obstacles_given) return {{c.obstacle.x0, c.obstacle.y0, c.obstacle.r, {}, "obstacle"}};
  std::vector<Hole> holes;
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) {
    const ObstacleSpec& o = c.obstacles[i];
    holes.push_back({o.x0, o.y0, o.r, o.points, "obstacles[" + std::to_string(i + 1) + "]"});
  }
  return holes;
}

// The hole's extent [x_min, x_max] × [y_min, y_max] (a polygon's lies at its corners).
std::array<double, 4> extent(const Hole& h) {
  if (!h.polygon()) return {h.x0 - h.r, h.x0 + h.r, h.y0 - h.r, h.y0 + h.r};
  std::array<double, 4> e = {INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Point& p : h.corners)
    e = {std::min(e[0], p.x()), std::max(e[1], p.x()), std::min(e[2], p.y()), std::max(e[3], p.y())};
  return e;
}

// The hole inside the box with room for a triangle between it and every side (a gap
// below half of hF leaves slivers); a circle at least six segments (a polygon's sides
// are cut as finely as they need, mesh_fluid_in_gmsh).
void check_hole_in_box(const Case& c, const Origin& o, const Hole& ob) {
  const auto& f = *c.fluid;
  const std::string whose = ob.key == "obstacle" ? "the obstacle's" : ob.key + "'s";
  if (!ob.polygon() && !(f.h <= ob.r))
    fail(o, "fluid.h", "= " + shortest(f.h) + " is larger than " + whose + " radius (the circle needs six segments)",
         "(0, " + ob.key + ".r = " + shortest(ob.r) + "] (" + o.value(ob.key + ".r", ob.r, "fluid.h") + ")");
  const double gap = f.h / 2;
  const auto [x_min, x_max, y_min, y_max] = extent(ob);
  const struct {
    const char* side;
    double distance;
  } sides[] = {{"left side x = 0", x_min},
               {"right side x = fluid.L1", f.L1 - x_max},
               {"bottom y = -fluid.H2", y_min + f.H2},
               {"top y = fluid.H1", f.H1 - y_max}};
  for (const auto& side : sides)
    if (!(side.distance >= gap))
      fail(o, ob.place_key(), ob.where() + "leaves " + approx(side.distance) + " to the fluid box's " + side.side,
           std::string(ob.polygon() ? "the polygon" : "the disk") + " inside (0, L1) x (-H2, H1) = (0, " +
               shortest(f.L1) + ") x (" + shortest(-f.H2) + ", " + shortest(f.H1) + ") at least fluid.h/2 = " +
               approx(gap) + " from every side");
}

// The distance between two holes' regions: 0 or less if they meet.
double distance_between(const Hole& a, const Hole& b) {
  if (a.polygon() && b.polygon()) return polygon_distance(a.corners, b.corners);
  if (!a.polygon() && !b.polygon()) return std::hypot(b.x0 - a.x0, b.y0 - a.y0) - a.r - b.r;
  const Hole &disk = a.polygon() ? b : a, &polygon = a.polygon() ? a : b;
  const Point centre(disk.x0, disk.y0);
  if (inside_polygon(polygon.corners, centre)) return -disk.r;
  return distance_to_boundary(polygon.corners, centre) - disk.r;
}

// Two holes of D must not meet: at least a triangle (fluid.h/2) between them.
void check_holes_apart(const Case& c, const Origin& o, const std::vector<Hole>& holes) {
  const double gap = c.fluid->h / 2;
  for (std::size_t j = 1; j < holes.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const Hole &a = holes[i], &b = holes[j];
      const double between = distance_between(a, b);
      const bool disks = !a.polygon() && !b.polygon();
      const std::string what = disks ? " (disks at (" + shortest(a.x0) + ", " + shortest(a.y0) + ") and (" +
                                           shortest(b.x0) + ", " + shortest(b.y0) + "))"
                                     : "";
      if (!(between >= gap))
        fail(o, b.key, (between <= 0 ? "overlaps " + a.key : "comes within " + approx(between) + " of " + a.key) + what,
             "in a fluid box, obstacles at least fluid.h/2 = " + approx(gap) + " apart (each is a hole of D)");
    }
}

// The generated box and its holes, at most the stated size.
void check_fluid_box(const Case& c, const Origin& o) {
  const auto& f = *c.fluid;
  const std::vector<Hole> holes = fluid_holes(c);
  double area = f.L1 * (f.H1 + f.H2);
  for (const Hole& hole : holes) {
    check_hole_in_box(c, o, hole);
    area -= hole.area();
  }
  check_holes_apart(c, o, holes);
  double estimate = 2.4 * area / (f.h * f.h);
  if (f.h_near > 0) {  // the band's triangles; a width: around the structure at rest at least
    const auto& s = c.structure;
    const double band_area = f.band_box ? ((*f.band_box)[2] - (*f.band_box)[0]) * ((*f.band_box)[3] - (*f.band_box)[1])
                                        : (s.L + 2 * f.band) * (s.H + 2 * f.band);
    estimate += 2.4 * std::min(band_area, area) / (f.h_near * f.h_near);
  }
  if (f.h_obstacles > 0) {  // a ring per hole, the size growing from h_obstacles: ∫ 2.4 P / (h_o + g s)² ds
    const double far = f.h_near > 0 ? std::min(f.h_near, f.h) : f.h;
    for (const Hole& hole : holes)
      if (f.h_obstacles < far) estimate += 2.4 * hole.perimeter() / kBandGrowth * (1 / f.h_obstacles - 1 / far);
  }
  const double limit = fluid_triangle_limit(f);
  if (estimate > limit)
    fail(o, "fluid.h", "= " + shortest(f.h) + " would need about " + approx(estimate) +
                           " triangles, above the limit of " + shortest(limit) +
                           (f.linear_solver == "petsc-iterative"
                                ? ""
                                : " (" + shortest(case_limits().fluid_triangles_iterative) +
                                      " with fluid.linear_solver = \"petsc-iterative\")"),
         ">= " + approx(std::sqrt(2.4 * area / limit)) + " for this box" +
             (f.h_near > 0 ? ", or a larger fluid.h_near or a smaller fluid.band" : "") +
             (f.h_obstacles > 0 ? ", or a larger fluid.h_obstacles" : ""));
}

// The refinement at the obstacles shapes the generated mesh, by a Gmsh size field.
void check_fluid_obstacle_refinement(const Case& c, const Origin& o) {
  const auto& f = *c.fluid;
  if (!(f.h_obstacles > 0)) return;
  if (!f.mesh.empty())
    fail(o, "fluid.h_obstacles", "= " + shortest(f.h_obstacles) + " refines the generated mesh, but fluid.mesh is set",
         "0 with fluid.mesh (refine the file's mesh itself)");
  if (f.method == "body-fitted")
    fail(o, "fluid.h_obstacles", "= " + shortest(f.h_obstacles) + " refines the fixed mesh of fluid.method = \"penalised\"",
         "0 with fluid.method = \"body-fitted\"");
  if (f.mesher != "gmsh")
    fail(o, "fluid.h_obstacles", "= " + shortest(f.h_obstacles) + " is a Gmsh size field, but fluid.mesher = \"" +
                                     f.mesher + "\"",
         "fluid.mesher = \"gmsh\" with fluid.h_obstacles, or 0");
}

// The band refinement shapes the generated mesh, and a band box must meet D.
void check_fluid_band(const Case& c, const Origin& o) {
  const auto& f = *c.fluid;
  check_fluid_obstacle_refinement(c, o);
  if (!(f.h_near > 0)) return;
  if (!f.mesh.empty())
    fail(o, "fluid.h_near", "= " + shortest(f.h_near) + " refines the generated mesh, but fluid.mesh is set",
         "0 with fluid.mesh (refine the file's mesh itself)");
  if (!f.band_box) return;
  const auto& b = *f.band_box;
  const double w = std::min(b[2], f.L1) - std::max(b[0], 0.0), h = std::min(b[3], f.H1) - std::max(b[1], -f.H2);
  if (!(w >= f.h_near && h >= f.h_near))
    fail(o, "fluid.band", "= [" + shortest(b[0]) + ", " + shortest(b[1]) + ", " + shortest(b[2]) + ", " +
                              shortest(b[3]) + "] does not meet the fluid box",
         "a box overlapping (0, " + shortest(f.L1) + ") x (" + shortest(-f.H2) + ", " + shortest(f.H1) +
             ") by at least fluid.h_near = " + shortest(f.h_near) + " each way");
}

// The structure at rest inside the fluid box (its clamped side on Σ1).
void check_structure_in_box(const Case& c, const Origin& o) {
  const auto& s = c.structure;
  const auto& f = *c.fluid;
  if (!(s.L < f.L1))
    fail(o, "structure.L", "= " + shortest(s.L) + " does not fit in the fluid box",
         "< fluid.L1 = " + shortest(f.L1) + " (" + o.value("fluid.L1", f.L1, "structure.L") + ")");
  if (!(s.H < f.H1))
    fail(o, "structure.H", "= " + shortest(s.H) + " does not fit in the fluid box",
         "< fluid.H1 = " + shortest(f.H1) + " (" + o.value("fluid.H1", f.H1, "structure.H") + ")");
}

// fluid.method = "body-fitted" meshes D minus the deformed structure on every pass, with
// hF everywhere: a fixed mesh file or a band of the fixed mesh cannot be honoured.
void check_fluid_method(const Case& c, const Origin& o) {
  const auto& f = *c.fluid;
  if (c.coupling.force_sampling > 1 && (f.method != "penalised" || c.structure.element != "P1"))
    fail(o, "coupling.force_sampling", "= " + std::to_string(c.coupling.force_sampling) +
                                       " refines how eq. (33) samples the penalised fluid on a P1 structure",
         "1 with fluid.method = \"body-fitted\" or structure.element = \"P2\"");
  if (f.method != "body-fitted") return;
  if (!f.mesh.empty())
    fail(o, "fluid.method", "= \"body-fitted\" remeshes the fluid around the deformed structure on every pass, "
                            "so it cannot use the mesh file fluid.mesh = \"" + f.mesh + "\"",
         "\"penalised\" with fluid.mesh, or \"body-fitted\" without it");
  if (f.h_near > 0)
    fail(o, "fluid.method", "= \"body-fitted\" does not refine a band (fluid.h_near = " + shortest(f.h_near) + ")",
         "\"body-fitted\" with fluid.h_near = 0, or \"penalised\"");
  // Its traction on the fitted interface is tested against P1 traces only (body_fitted_force.hpp).
  if (c.structure.element != "P1")
    fail(o, "structure.element", "= \"" + c.structure.element + "\": fluid.method = \"body-fitted\" transfers its "
                                 "traction to P1 structures only",
         "\"P1\" with fluid.method = \"body-fitted\", or \"P2\" with \"penalised\"");
}

// SPEC §10 "Box sides": at least one side must be an outflow. There is no
// mean-pressure constraint (SPEC §3, Decision): without a traction-free side the
// pressure is fixed only up to a constant and the discrete system is singular, and
// an inflow (always into the box) could not balance: ∫_∂D v·n = 0 has no solution.
void check_fluid_sides(const Case& c, const Origin& o) {
  const auto& f = *c.fluid;
  const auto& sides = f.sides;
  if (std::find(sides.begin(), sides.end(), "outflow") != sides.end()) return;
  const auto inflow = std::find(sides.begin(), sides.end(), "inflow");
  const std::string key = std::string("fluid.") + kBoxSideKeys[inflow != sides.end() ? inflow - sides.begin() : 1];
  std::string list;
  for (std::size_t k = 0; k < sides.size(); ++k) list += (k ? ", " : "") + std::string(kBoxSideKeys[k]) + " = \"" + sides[k] + "\"";
  fail(o, key, "leaves the fluid box without an outflow side (" + list + "): " +
                   (inflow != sides.end() ? "the inflow has nowhere to go, and " : "") +
                   "the pressure would be fixed only up to a constant",
       "at least one of fluid.left, fluid.bottom, fluid.right, fluid.top = \"outflow\"");
}

// The paper's gap is the graph of the disk's upper arc over Γ_C: it has no meaning on
// the rest of the boundary. The body-fitted fluid cannot follow contact at all: with
// [[obstacles]] it takes "normal" (their only gap) and refuses a structure closer than
// its min_gap·hF to any of them (BodyFittedFluid::check_gap).
void check_contact_gap(const Case& c, const Origin& o) {
  if (c.contact.gap == "paper" && c.contact.boundary != "Gamma_C")
    fail(o, "contact.boundary", "= \"" + c.contact.boundary + "\" needs contact.gap = \"normal\" (eq. 15's graph covers Gamma_C only)",
         "\"Gamma_C\" with contact.gap = \"paper\"");
  if (c.contact.gap == "normal" && c.fluid && c.fluid->method == "body-fitted" && !c.obstacles_given)
    fail(o, "contact.gap", "= \"normal\" has no contact to follow with fluid.method = \"body-fitted\" and [obstacle] (it refuses contact)",
         "\"paper\" with fluid.method = \"body-fitted\" and [obstacle], or \"normal\" with [[obstacles]]");
}

// [[obstacles]] in a coupled run (SPEC §9): every obstacle is a hole of D: of the
// generated box (checked with it, check_fluid_box) or of the mesh file (checked when it
// is read, run/hole_checks.cpp), so disks and polygons, also of the body-fitted mesh
// (its holes Sigma_5_i, coupling/body_fitted_fluid.hpp).
void check_fluid_obstacles(const Case& c, const Origin& o) {
  for (std::size_t i = 0; i < c.obstacles.size(); ++i)
    if (c.obstacles[i].shape == "half-plane")
      fail(o, "obstacles[" + std::to_string(i + 1) + "].shape",
           "= \"half-plane\" is for contact problems only (no [fluid]): a fluid box's obstacles are its holes",
           "\"disk\" or \"polygon\" with a [fluid] section");
}

// [[obstacles]] (SPEC §9): the signed-distance gap only (eq. 15 is the graph of one
// disk); with a fluid, holes of D (check_fluid_obstacles); a generated rectangle's Γ_C
// is the paper disk's span, so there every edge off Γ_D is the candidate.
void check_obstacles(const Case& c, const Origin& o) {
  if (!c.obstacles_given) return;
  if (c.obstacle_given)
    fail(o, "obstacles", "and [obstacle] are both given", "[obstacle] (the paper's disk) or [[obstacles]], not both");
  if (c.contact.gap != "normal" && c.structure.shape != "none")  // no structure: no contact
    fail(o, "contact.gap", "= \"" + c.contact.gap + "\" cannot use [[obstacles]] (eq. 15 is the graph of one disk)",
         "\"normal\" with [[obstacles]]");
  if (c.fluid) check_fluid_obstacles(c, o);
  if (c.structure.rectangle() && c.contact.boundary != "all")
    fail(o, "contact.boundary", "= \"" + c.contact.boundary + "\": the generated rectangle's Gamma_C follows [obstacle]'s disk",
         "\"all\" with [[obstacles]] and a generated structure");
}

}  // namespace

// structure.shape = "none": the fluid alone, in a penalised box (run/fluid_problem.cpp).
void check_no_structure(const Case& c, const Origin& o) {
  const char* allowed = "structure.shape = \"none\" with a [fluid] section, fluid.method = \"penalised\", and a band given as a box";
  if (!c.fluid) fail(o, "structure.shape", "= \"none\" leaves nothing to solve without a [fluid] section", allowed);
  if (c.fluid->method != "penalised")
    fail(o, "fluid.method", "= \"" + c.fluid->method + "\" meshes around a structure; structure.shape = \"none\" has none", allowed);
  if (c.fluid->h_near > 0 && !c.fluid->band_box)
    fail(o, "fluid.band", "= " + shortest(c.fluid->band) + " is a width around the structure; structure.shape = \"none\" has none",
         "fluid.band = [x_min, y_min, x_max, y_max] with fluid.h_near, or fluid.h_near = 0");
  if (!c.output.probes.empty())  // a probe is a material point of the structure (SPEC §11)
    fail(o, "output.probes", "names points of the structure; structure.shape = \"none\" has none",
         "no output.probes with structure.shape = \"none\"");
}

// [time] (SPEC §12), so far for the fluid alone on the penalised method's fixed mesh,
// whose inertia needs its density.
// A structure in time (SPEC §12): its density, and what its mass matrix allows.
void check_structure_in_time(const Case& c, const Origin& origin) {
  const auto& s = c.structure;
  if (c.fluid && c.fluid->method != "penalised")
    fail(origin, "fluid.method", "= \"" + c.fluid->method + "\" has no time stepping", "\"penalised\" with [time]");
  if (c.fluid && c.fluid->rho == 0)
    fail(origin, "fluid.rho", "is required with [time] (the fluid's inertia ρ ∂v/∂t)", "a density in [1e-30, 1e30] kg/m³");
  if (c.fluid && c.coupling.max_iterations == 0)
    fail(origin, "coupling.max_iterations", "= 0 (the fluid around the structure at rest) has no time stepping",
         "at least 1 with [time] and a structure");
  if (s.rho == 0)
    fail(origin, "structure.rho", "is required with [time] and a structure (its inertia ρ_S ü)",
         "a density in [1e-30, 1e30] kg/m³");
  if (s.mass == "redistributed" && s.element != "P1")
    fail(origin, "structure.mass", "= \"redistributed\" lumps P1's mass; structure.element = \"" + s.element +
         "\" has none to lump", "\"consistent\" with structure.element = \"P2\"");
}

void check_time(const Case& c, const Origin& origin) {
  if (!c.structure.clamped && !c.time)
    fail(origin, "structure.clamped", "= false leaves a free body, which only inertia holds",
         "true, or false with a [time] section");
  if (!c.time) return;
  if (c.time->start_from == "steady" && !c.structure.clamped)
    fail(origin, "time.start_from", "= \"steady\" needs a steady problem, and a free body (structure.clamped = false) "
         "has none", "\"rest\" for a free body");
  if (c.structure.shape != "none") return check_structure_in_time(c, origin);
  if (!c.fluid) return;  // nothing at all: check_no_structure says so
  if (c.fluid->method != "penalised")
    fail(origin, "fluid.method", "= \"" + c.fluid->method + "\" has no time stepping", "\"penalised\" with [time]");
  if (c.fluid->rho == 0)
    fail(origin, "fluid.rho", "is required with [time] (the fluid's inertia ρ ∂v/∂t)",
         "a density in [1e-30, 1e30] kg/m³");
  if (c.fluid->taylor_hood() && c.fluid->navier_stokes() && c.time->convection != "implicit")
    fail(origin, "time.convection", "= \"" + c.time->convection + "\" is the mini element's; fluid.element = "
         "\"taylor-hood\" takes Newton's method in every step", "\"implicit\" with fluid.element = \"taylor-hood\"");
}

void check_case(const Case& c, const Origin& origin) {
  check_time(c, origin);
  if (!c.output.fluid_probes.empty() && !c.fluid)  // points of the flow (SPEC §10)
    fail(origin, "output.fluid_probes", "names points of the fluid, and the case has no [fluid] section",
         "output.fluid_probes with a [fluid] section");
  if (c.structure.shape == "none") {
    check_no_structure(c, origin);
    check_obstacles(c, origin);
    check_fluid_band(c, origin);
    check_fluid_sides(c, origin);
    if (c.fluid->mesh.empty()) check_fluid_box(c, origin);
    return;
  }
  // With a mesh file or a script the structure's geometry is the mesh's, checked when
  // it is made (run/mesh_checks.cpp): L and H, if given, must then equal its extent.
  check_obstacles(c, origin);
  const bool rectangle = c.structure.rectangle();
  if (rectangle) {
    check_structure_mesh_size(c, origin);
    if (!c.obstacles_given) {  // Γ_C and the disk of [obstacle]
      check_contact_zone(c, origin);
      check_rectangle_against_obstacle(c, origin);
    }
    check_strain(c, origin);
  }
  check_contact_gap(c, origin);
  if (!c.fluid) return;
  if (c.fluid->taylor_hood())  // the coupling's χ, penalty and transfers are the mini element's
    fail(origin, "fluid.element", "= \"taylor-hood\" solves the fluid alone so far, and this case has a structure",
         "\"mini\" with a structure, \"taylor-hood\" with structure.shape = \"none\"");
  if (rectangle) check_structure_in_box(c, origin);
  check_fluid_sides(c, origin);
  check_fluid_method(c, origin);
  check_fluid_band(c, origin);
  if (c.fluid->mesh.empty()) check_fluid_box(c, origin);
}

}  // namespace fsi::case_detail

namespace fsi {

// The loads' strain scale (|f_S|·diam + |h_N|)/E: linear elasticity means ≪ 1. A load
// given as an expression (SPEC §10) enters by its magnitude, the largest of its values
// at 5 × 5 points of its box at t = 0 (io/case.hpp, above StructureParams): an estimate,
// as the scale itself is.
std::string load_strain_problem(const Case& c, double diam) {
  using case_detail::kMaxStrainScale;
  const auto& s = c.structure;
  const double strain = (s.f.norm() * diam + s.h_N.norm()) / s.E;
  if (!(strain <= kMaxStrainScale))
    return "structure.E = " + shortest(s.E) + " is too soft for the loads: they strain the structure by about " +
           approx(strain) + " ((|structure.f| * diam + |structure.h_N|) / E); allowed: a strain scale <= " +
           shortest(kMaxStrainScale) + ": a larger structure.E or smaller loads";
  if (!c.fluid) return "";
  const auto& f = *c.fluid;
  // The fluid's stresses on the structure: viscous (μ Vmax / hF) and its weight.
  const double fluid_strain = (f.mu * std::abs(f.Vmax) / f.h + f.f.norm() * diam) / s.E;
  if (!(fluid_strain <= kMaxStrainScale))
    return "structure.E = " + shortest(s.E) + " is too soft for the fluid's stresses: they strain the structure by about " +
           approx(fluid_strain) + " ((fluid.mu * |fluid.Vmax| / fluid.h + |fluid.f| * diam) / E); allowed: a strain "
           "scale <= " + shortest(kMaxStrainScale) + ": a larger structure.E, or smaller fluid loads";
  return "";
}

}  // namespace fsi
