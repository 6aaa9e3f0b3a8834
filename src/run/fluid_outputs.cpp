#include "run/fluid_outputs.hpp"

#include <cmath>
#include <numbers>

#include "io/figure.hpp"
#include "io/vtu.hpp"

namespace fsi {

void write_fluid_vtu(const std::string& path, const Mesh& mesh, const FluidSolution& s,
                     const Eigen::VectorXd& chi) {
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  write_vtu(path, mesh,
            {vector_field("velocity", s.v1, s.v2), scalar_field("velocity_magnitude", magnitude),
             scalar_field("pressure", s.p), scalar_field("chi", chi, true)});
}

void write_fluid_png(const std::string& path, const Case& c, const Mesh& fluid_mesh,
                     const FluidSolution& s, const Mesh& deformed_structure,
                     const std::vector<int>& contact_vertices, const std::string& title,
                     const std::string& note) {
  const FluidParams& f = *c.fluid;
  const ObstacleParams& o = c.obstacle;
  const double pad = 0.02 * f.L1;
  Figure fig({-pad, f.L1 + pad, -f.H2 - pad, f.H1 + pad}, 520, title);
  fig.note(note);
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  fig.shade(fluid_mesh, magnitude, 0.0, magnitude.maxCoeff());
  std::vector<Point> disk;
  for (int k = 0; k < 240; ++k) {
    const double t = 2 * std::numbers::pi * k / 240;
    disk.emplace_back(o.x0 + o.r * std::cos(t), o.y0 + o.r * std::sin(t));
  }
  fig.filled_polygon(disk, {0.82, 0.82, 0.82});
  fig.polyline(disk, {0.1, 0.1, 0.1}, 1.0, true);
  for (const auto& loop : boundary_loops(deformed_structure)) fig.polyline(loop, {1, 1, 1}, 1.6, true);
  for (int v : contact_vertices) fig.marker(deformed_structure.vertices[v], {0.9, 0.1, 0.1}, 3.5);
  fig.axes("x (m)", "y (m)");
  fig.colour_bar(0.0, magnitude.maxCoeff(), "|v| (m/s)");
  fig.legend({{{1, 1, 1}, "structure"}, {{0.82, 0.82, 0.82}, "obstacle"}, {{0.9, 0.1, 0.1}, "contact"}});
  fig.save_png(path);
}

}  // namespace fsi
