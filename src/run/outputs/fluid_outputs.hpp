// fluid.vtu and the velocity picture (the paper's Fig. 9).
#pragma once

#include <optional>
#include <string>

#include "fluid/penalised_stokes.hpp"
#include "io/figure.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// Point data: velocity (P1 part), velocity_magnitude, pressure; cell data: chi. In
// the case's output.vtu_format.
void write_fluid_vtu(const std::string& path, const Case& c, const Mesh& mesh,
                     const FluidSolution& s, const Eigen::VectorXd& chi);

// |v| over D with the deformed structure outlined, the obstacle, and the contact
// zone (vertices of `contact_vertices`, deformed) in red.
void write_fluid_png(const std::string& path, const Case& c, const Mesh& fluid_mesh,
                     const FluidSolution& s, const Mesh& deformed_structure,
                     const std::vector<int>& contact_vertices, const std::string& title,
                     const std::string& note, const WorldBox* zoom = nullptr);
// The same picture as PNG bytes, to be written later: PenalisedProblem::measure
// (run/penalised_problem.cpp) draws it on a second core while the summary and the
// other files are written.
std::string fluid_png(const std::string& name, const Case& c, const Mesh& fluid_mesh, const FluidSolution& s,
                      const Mesh& deformed_structure, const std::vector<int>& contact_vertices,
                      const std::string& title, const std::string& note, const WorldBox* zoom = nullptr);
// That picture's world box (the fluid box with a 2 % margin) and plot width in pixels:
// Navier–Stokes (SPEC §10): the title says the model and the Reynolds number, and
// velocity vectors are drawn over |v|; `zoom` (null: the whole box) draws a part.
// The wake of the first obstacle for a zoomed picture: 2 widths upstream, 6
// downstream, 2 to each side (clipped to the box); none for Stokes or without an obstacle.
std::optional<WorldBox> wake_box(const Case& c);
// Figure(fluid_figure_box(f), kFluidFigureWidth, ...).pixel(x) is where x is drawn.
WorldBox fluid_figure_box(const FluidParams& f);
inline constexpr int kFluidFigureWidth = 520;

}  // namespace fsi
