#include "run/outputs/fluid_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "io/atomic_file.hpp"
#include "fem/point_locator.hpp"
#include "fluid/fluid_field.hpp"
#include "io/vtu.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/fluid_setup.hpp"
#include "run/outputs/structure_outputs.hpp"

namespace fsi {

void write_fluid_vtu(const std::string& path, const Case& c, const Mesh& mesh,
                     const FluidSolution& s, const Eigen::VectorXd& chi) {
  write_vtu(path, mesh, fluid_arrays(mesh, s, chi).fields, vtu_format(c.output.vtu_format));
}

namespace {

constexpr Rgb kInflowColour{0.15, 0.35, 0.95}, kOutflowColour{0.1, 0.75, 0.25};

// The inflow and outflow sides (fluid.left, ...: SPEC §10) as thick lines along the
// box, and their legend entries.
std::vector<std::pair<Rgb, std::string>> draw_box_sides(Figure& fig, const FluidParams& f) {
  const Point corner[4] = {{0, -f.H2}, {f.L1, -f.H2}, {f.L1, f.H1}, {0, f.H1}};
  // Σ1 left, Σ2 bottom, Σ3 right, Σ4 top: from corner a to corner b.
  const int ends[4][2] = {{3, 0}, {0, 1}, {1, 2}, {2, 3}};
  bool drawn[2] = {false, false};
  for (int k = 0; k < 4; ++k) {
    if (f.sides[k] == "wall") continue;
    const bool in = f.sides[k] == "inflow";
    fig.polyline({corner[ends[k][0]], corner[ends[k][1]]}, in ? kInflowColour : kOutflowColour, 4.0, false);
    drawn[in ? 0 : 1] = true;
  }
  std::vector<std::pair<Rgb, std::string>> entries;
  if (drawn[0]) entries.push_back({kInflowColour, "inflow"});
  if (drawn[1]) entries.push_back({kOutflowColour, "outflow"});
  return entries;
}

}  // namespace

WorldBox fluid_figure_box(const FluidParams& f) {
  const double pad = 0.02 * f.L1;
  return {-pad, f.L1 + pad, -f.H2 - pad, f.H1 + pad};
}

namespace {

// The velocity's direction on a regular grid of 60 columns, arrows of one length (the
// colour under them gives |v|): where the flow separates, the slow recirculation shows
// as arrows turned back (SPEC §10), which arrows scaled by |v| would hide. Drawn for
// Navier–Stokes; points outside D (holes) are skipped, and where |v| < 1e-3 max |v|.
void draw_velocity_vectors(Figure& fig, const WorldBox& box, const Mesh& fluid_mesh, const FluidSolution& s) {
  const PointLocator locator(fluid_mesh);
  const FluidField field(locator, s);
  const double step = (box.x_max - box.x_min) / 60;
  std::vector<std::pair<Point, Point>> samples;  // point, velocity
  double v_max = 0;
  for (double y = box.y_min + step / 2; y < box.y_max; y += step)
    for (double x = box.x_min + step / 2; x < box.x_max; x += step) {
      const auto where = locator.locate(Point(x, y));
      if (!where) continue;
      const Point v = field.at(*where).v;
      samples.push_back({Point(x, y), v});
      v_max = std::max(v_max, v.norm());
    }
  if (!(v_max > 0)) return;
  for (const auto& [x, v] : samples) {
    if (!(v.norm() >= 1e-3 * v_max)) continue;
    const Point d = v.normalized() * (0.7 * step);
    fig.arrow(x - d / 2, x + d / 2, {0.1, 0.1, 0.1}, 0.8);
  }
}

// "Navier-Stokes at Re = 20: |v| and velocity vectors", a figure's title.
std::string flow_words(const Case& c) {
  const Reynolds re = reynolds_number(c);
  char text[96];
  std::snprintf(text, sizeof text, "Navier-Stokes at Re = %.3g: |v| and velocity vectors", re.value);
  return std::isfinite(re.value) ? text : "Navier-Stokes: |v| and velocity vectors";
}

// The velocity picture, drawn.
void draw_fluid(Figure& fig, const Case& c, const WorldBox& box, const Mesh& fluid_mesh, const FluidSolution& s,
                const Mesh& deformed_structure, const std::vector<int>& contact_vertices, const std::string& note) {
  fig.note(note);
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  fig.shade(fluid_mesh, magnitude, 0.0, magnitude.maxCoeff());
  if (c.fluid->navier_stokes()) draw_velocity_vectors(fig, box, fluid_mesh, s);
  for (const std::vector<Point>& hole : obstacle_outlines(c, box)) {  // every hole of D
    fig.filled_polygon(hole, {0.82, 0.82, 0.82});
    fig.polyline(hole, {0.1, 0.1, 0.1}, 1.0, true);
  }
  for (const auto& loop : boundary_loops(deformed_structure)) fig.polyline(loop, {1, 1, 1}, 1.6, true);
  for (int v : contact_vertices) fig.marker(deformed_structure.vertices[v], {0.9, 0.1, 0.1}, 3.5);
  std::vector<std::pair<Rgb, std::string>> legend = draw_box_sides(fig, *c.fluid);
  fig.axes("x (m)", "y (m)");
  fig.colour_bar(0.0, magnitude.maxCoeff(), "|v| (m/s)");
  legend.insert(legend.begin(), {{{1, 1, 1}, "structure"}, {{0.82, 0.82, 0.82}, "obstacle"}, {{0.9, 0.1, 0.1}, "contact"}});
  fig.legend(legend);
}

}  // namespace

std::string fluid_png(const std::string& name, const Case& c, const Mesh& fluid_mesh, const FluidSolution& s,
                      const Mesh& deformed_structure, const std::vector<int>& contact_vertices,
                      const std::string& title, const std::string& note, const WorldBox* zoom) {
  const WorldBox box = zoom ? *zoom : fluid_figure_box(*c.fluid);
  Figure fig(box, kFluidFigureWidth, c.fluid->navier_stokes() ? c.name + ": " + flow_words(c) : title);
  draw_fluid(fig, c, box, fluid_mesh, s, deformed_structure, contact_vertices, note);
  return fig.png(name);
}

std::optional<WorldBox> wake_box(const Case& c) {
  const Reynolds re = reynolds_number(c);
  const FluidParams& f = *c.fluid;
  if (!std::isfinite(re.value) || re.length.find("obstacle") == std::string::npos) return std::nullopt;
  Point centre;
  if (!c.obstacles_given) centre = Point(c.obstacle.x0, c.obstacle.y0);
  else if (c.obstacles.front().shape == "disk") centre = Point(c.obstacles.front().x0, c.obstacles.front().y0);
  else {
    centre.setZero();
    for (const Point& p : c.obstacles.front().points) centre += p / static_cast<double>(c.obstacles.front().points.size());
  }
  int inflow = 0;
  while (f.sides[inflow] != "inflow") ++inflow;
  // The flow's direction: from Σ1 (left) +x, Σ2 (bottom) +y, Σ3 −x, Σ4 −y.
  const Point along = inflow == 0 ? Point(1, 0) : inflow == 1 ? Point(0, 1) : inflow == 2 ? Point(-1, 0) : Point(0, -1);
  const Point a = centre - 2 * re.L * along, b = centre + 6 * re.L * along;
  const Point across(std::abs(along.y()), std::abs(along.x()));
  const Point lo = a.cwiseMin(b) - 2 * re.L * across, hi = a.cwiseMax(b) + 2 * re.L * across;
  WorldBox box{std::max(lo.x(), 0.0), std::min(hi.x(), f.L1), std::max(lo.y(), -f.H2), std::min(hi.y(), f.H1)};
  if (!(box.x_max > box.x_min && box.y_max > box.y_min)) return std::nullopt;
  return box;
}

void write_fluid_png(const std::string& path, const Case& c, const Mesh& fluid_mesh,
                     const FluidSolution& s, const Mesh& deformed_structure,
                     const std::vector<int>& contact_vertices, const std::string& title,
                     const std::string& note, const WorldBox* zoom) {
  write_file_atomically(
      path, fluid_png(path, c, fluid_mesh, s, deformed_structure, contact_vertices, title, note, zoom));
}

}  // namespace fsi
