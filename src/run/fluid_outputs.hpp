// fluid.vtu and the velocity picture (the paper's Fig. 9).
#pragma once

#include <string>

#include "fluid/penalised_stokes.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// Point data: velocity (P1 part), velocity_magnitude, pressure; cell data: chi.
void write_fluid_vtu(const std::string& path, const Mesh& mesh, const FluidSolution& s,
                     const Eigen::VectorXd& chi);

// |v| over D with the deformed structure outlined, the obstacle, and the contact
// zone (vertices of `contact_vertices`, deformed) in red.
void write_fluid_png(const std::string& path, const Case& c, const Mesh& fluid_mesh,
                     const FluidSolution& s, const Mesh& deformed_structure,
                     const std::vector<int>& contact_vertices, const std::string& title,
                     const std::string& note);

}  // namespace fsi
