#include "run/outputs/structure_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "io/figure.hpp"
#include "io/vtu.hpp"
#include "run/outputs/field_arrays.hpp"

namespace fsi {
namespace {

const Rgb kRed{0.85, 0.1, 0.1}, kGrey{0.55, 0.55, 0.55}, kDark{0.15, 0.15, 0.15},
    kOrange{0.95, 0.55, 0.1};

std::vector<Point> disk_polygon(double x0, double y0, double r, int segments = 360) {
  std::vector<Point> p;
  for (int k = 0; k < segments; ++k) {
    const double t = 2 * std::numbers::pi * k / segments;
    p.emplace_back(x0 + r * std::cos(t), y0 + r * std::sin(t));
  }
  return p;
}

// The frame `box` cut by the half-plane {(x − q)·n ≤ 0} (one Sutherland–Hodgman step).
std::vector<Point> half_plane_polygon(const Point& q, const Point& n, const WorldBox& box) {
  const std::vector<Point> frame = {{box.x_min, box.y_min}, {box.x_max, box.y_min}, {box.x_max, box.y_max},
                                    {box.x_min, box.y_max}};
  std::vector<Point> out;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const Point &a = frame[i], &b = frame[(i + 1) % frame.size()];
    const double da = (a - q).dot(n), db = (b - q).dot(n);
    if (da <= 0) out.push_back(a);
    if ((da < 0) != (db < 0) && da != db) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// The lowest point of the obstacles' tops the frame should show.
double lowest_obstacle_top(const Case& c) {
  if (!c.obstacles_given) return c.obstacle.y0 + 0.3 * c.obstacle.r;
  double y = INFINITY;
  for (const ObstacleSpec& o : c.obstacles) {
    if (o.shape == "polygon") {  // its top third
      double lo = INFINITY, hi = -INFINITY;
      for (const Point& p : o.points) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
      y = std::min(y, hi - (hi - lo) / 3);
    } else {
      y = std::min(y, o.shape == "disk" ? o.y0 + 0.3 * o.r : o.point.y() - 0.002);
    }
  }
  return y;
}

}  // namespace

std::vector<std::vector<Point>> obstacle_outlines(const Case& c, const WorldBox& box) {
  if (!c.obstacles_given) return {disk_polygon(c.obstacle.x0, c.obstacle.y0, c.obstacle.r)};
  std::vector<std::vector<Point>> out;
  for (const ObstacleSpec& o : c.obstacles)
    out.push_back(o.shape == "disk"      ? disk_polygon(o.x0, o.y0, o.r)
                  : o.shape == "polygon" ? o.points
                                         : half_plane_polygon(o.point, o.normal, box));
  return out;
}

void write_structure_vtu(const std::string& path, const Case& c, const StructureSetup& s,
                         const ContactSolution& solution, bool deformed) {
  const FieldArrays a = structure_arrays(s, solution);
  const VtuFormat format = vtu_format(c.output.vtu_format);
  const std::vector<Point>& nodes = deformed ? a.deformed : a.vertices;
  if (s.p2()) {  // the P2 elements as VTK's quadratic triangles on the nodes
    std::vector<std::array<int, 6>> cells(a.cells.rows());
    for (Eigen::Index t = 0; t < a.cells.rows(); ++t)
      for (int k = 0; k < 6; ++k) cells[t][k] = a.cells(t, k);
    write_quadratic_vtu(path, nodes, cells, a.fields, format);
    return;
  }
  Mesh points = s.mesh();
  points.vertices = nodes;
  write_vtu(path, points, a.fields, format);
}

namespace {

// The frame: the structure before and after, and the top of the obstacle, padded by 6 %.
WorldBox structure_frame(const Case& c, const Mesh& ref, const Mesh& def) {
  WorldBox box{INFINITY, -INFINITY, lowest_obstacle_top(c), -INFINITY};
  for (const Mesh* m : {&ref, &def})
    for (const Point& p : m->vertices) {
      box.x_min = std::min(box.x_min, p.x());
      box.x_max = std::max(box.x_max, p.x());
      box.y_min = std::min(box.y_min, p.y());
      box.y_max = std::max(box.y_max, p.y());
    }
  const double pad = 0.06 * std::max(box.x_max - box.x_min, box.y_max - box.y_min);
  return {box.x_min - pad, box.x_max + pad, box.y_min - pad, box.y_max + pad};
}

// structure.f as the note shows it: "(0, -1.1e+04)", an expression (SPEC §10) as its text.
std::string body_force_words(const StructureParams& s) {
  std::string words = "(";
  for (int c = 0; c < 2; ++c) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", s.f[c]);
    words += (c ? ", " : "") + (s.f_expression[c].empty() ? std::string(number) : s.f_expression[c]);
  }
  return words + ")";
}

// The two lines under the title: the load, material and mesh; the contact zone.
void structure_notes(Figure& fig, const Case& c, const StructureSetup& s, const ContactSolution& solution,
                     double max_u) {
  const Mesh& ref = s.mesh();
  const ContactSummary cs = summarize_contact(*s.solver, solution);
  char line[256];
  std::snprintf(line, sizeof line,
                "f_S = %s N/m^3, E = %g Pa, nu = %g;  %smesh %d triangles / %d %s;  "
                "max |u| = %.4g m",
                body_force_words(c.structure).c_str(), c.structure.E, c.structure.nu, s.p2() ? "P2 " : "",
                s.p2() ? s.p2()->mesh().num_triangles() : ref.num_triangles(), ref.num_vertices(),
                s.p2() ? "nodes" : "vertices", max_u);
  fig.note(line);
  if (cs.active_nodes > 0)
    std::snprintf(line, sizeof line,
                  "contact on %d node(s), X1 in [%.5g, %.5g] m, peak pressure %.4g Pa",
                  cs.active_nodes, cs.x_min, cs.x_max, cs.max_multiplier);
  else
    std::snprintf(line, sizeof line, "no contact");
  fig.note(line);
}

// Γ_C on the reference outline, and the active part on the deformed one.
void draw_contact_zone(Figure& fig, const StructureSetup& s, const ContactSolution& solution, const Mesh& def) {
  const Mesh& ref = s.mesh();
  const std::vector<BoundaryEdge> gamma_c = ref.edges_on(ref.label("Gamma_C"));
  for (const auto& e : gamma_c) fig.polyline({ref.vertices[e.v[0]], ref.vertices[e.v[1]]}, kOrange, 3.0);
  const std::vector<int> active = active_vertices(*s.solver, solution);
  for (const auto& e : gamma_c) {
    const bool a0 = std::find(active.begin(), active.end(), e.v[0]) != active.end();
    const bool a1 = std::find(active.begin(), active.end(), e.v[1]) != active.end();
    if (a0 && a1) fig.polyline({def.vertices[e.v[0]], def.vertices[e.v[1]]}, kRed, 4.0);
  }
  for (int v : active) fig.marker(def.vertices[v], kRed, 4.5);
}

}  // namespace

void write_structure_png(const std::string& path, const Case& c, const StructureSetup& s,
                         const ContactSolution& solution, const std::string& title) {
  const Mesh& ref = s.mesh();
  const Eigen::VectorXd u1 = component(solution.u, 0), u2 = component(solution.u, 1);
  const Mesh def = displaced(ref, u1, u2);
  const Eigen::VectorXd magnitude = (u1.array().square() + u2.array().square()).sqrt();
  const WorldBox box = structure_frame(c, ref, def);
  const int width = static_cast<int>(std::clamp(1100.0 * (box.x_max - box.x_min) / (box.y_max - box.y_min), 500.0, 1100.0));
  const bool several = c.obstacles_given && c.obstacles.size() != 1;
  Figure fig(box, width,
             title.empty() ? c.name + ": deformed structure in contact with the obstacle" + (several ? "s" : "") : title);
  structure_notes(fig, c, s, solution, magnitude.maxCoeff());
  for (const auto& outline : obstacle_outlines(c, box)) {
    if (outline.size() < 3) continue;
    fig.filled_polygon(outline, {0.82, 0.82, 0.82});
    fig.polyline(outline, kDark, 1.2, true);
  }
  fig.shade(def, magnitude, 0.0, magnitude.maxCoeff());
  for (const auto& loop : boundary_loops(ref)) fig.polyline(loop, kGrey, 1.2, true, true);
  for (const auto& loop : boundary_loops(def)) fig.polyline(loop, kDark, 1.0, true);
  draw_contact_zone(fig, s, solution, def);
  fig.axes("x (m)", "y (m)");
  fig.colour_bar(0.0, magnitude.maxCoeff(), "|u| (m)");
  fig.legend({{kGrey, "undeformed (dashed)"},
              {kOrange, "Gamma_C"},
              {kRed, "contact zone"},
              {{0.82, 0.82, 0.82}, "rigid obstacle"}});
  fig.save_png(path);
}

}  // namespace fsi
