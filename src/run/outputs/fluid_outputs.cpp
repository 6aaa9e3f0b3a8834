#include "run/outputs/fluid_outputs.hpp"

#include <cmath>
#include <numbers>

#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "run/outputs/structure_outputs.hpp"

namespace fsi {

void write_fluid_vtu(const std::string& path, const Case& c, const Mesh& mesh,
                     const FluidSolution& s, const Eigen::VectorXd& chi) {
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  write_vtu(path, mesh,
            {vector_field("velocity", s.v1, s.v2), scalar_field("velocity_magnitude", magnitude),
             scalar_field("pressure", s.p), scalar_field("chi", chi, true)},
            vtu_format(c.output.vtu_format));
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

// The velocity picture, drawn.
void draw_fluid(Figure& fig, const Case& c, const WorldBox& box, const Mesh& fluid_mesh, const FluidSolution& s,
                const Mesh& deformed_structure, const std::vector<int>& contact_vertices, const std::string& note) {
  fig.note(note);
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  fig.shade(fluid_mesh, magnitude, 0.0, magnitude.maxCoeff());
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
                      const std::string& title, const std::string& note) {
  const WorldBox box = fluid_figure_box(*c.fluid);
  Figure fig(box, kFluidFigureWidth, title);
  draw_fluid(fig, c, box, fluid_mesh, s, deformed_structure, contact_vertices, note);
  return fig.png(name);
}

void write_fluid_png(const std::string& path, const Case& c, const Mesh& fluid_mesh,
                     const FluidSolution& s, const Mesh& deformed_structure,
                     const std::vector<int>& contact_vertices, const std::string& title,
                     const std::string& note) {
  write_file_atomically(
      path, fluid_png(path, c, fluid_mesh, s, deformed_structure, contact_vertices, title, note));
}

}  // namespace fsi
