// A final state's fields as arrays (issue 31: the Python module's Result.structure and
// Result.fluid): what structure.vtu and fluid.vtu hold, built by one function each so
// that the files and the arrays cannot differ.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "fluid/penalised_stokes.hpp"
#include "io/vtu.hpp"
#include "mesh/mesh.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

using CellArray = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct FieldArrays {
  std::vector<Point> vertices;  // the nodes in the reference configuration (P2: vertices, then midpoints)
  std::vector<Point> deformed;  // the structure's nodes displaced (empty for the fluid)
  CellArray cells;              // one row per triangle: 3 node indices (P1) or 6 (P2, VTK's order)
  std::vector<VtuField> fields; // point data on the nodes, cell data per triangle (VtuField::on_cells)
};

// The fields of a run's final state; either absent where the run has none (a contact
// run has no fluid; a failure before the first solve has neither).
struct FinalFields {
  std::optional<FieldArrays> structure, fluid;
};

// displacement, displacement_magnitude, contact_multiplier, contact_status (per node),
// von_mises (per triangle).
FieldArrays structure_arrays(const StructureSetup& s, const ContactSolution& solution);
// The same, or nothing while `solution` holds no displacement of s's mesh (a run that
// failed before its first structure solve).
std::optional<FieldArrays> structure_arrays_if_solved(const StructureSetup& s, const ContactSolution& solution);
// velocity (its P1 part), velocity_magnitude, pressure (per vertex), chi (per triangle).
FieldArrays fluid_arrays(const Mesh& mesh, const FluidSolution& s, const Eigen::VectorXd& chi);

}  // namespace fsi
