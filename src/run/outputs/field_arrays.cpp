#include "run/outputs/field_arrays.hpp"

#include "solid/stress.hpp"

namespace fsi {
namespace {

CellArray triangle_cells(const Mesh& mesh) {
  CellArray cells(mesh.num_triangles(), 3);
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int a = 0; a < 3; ++a) cells(t, a) = mesh.triangles[t][a];
  return cells;
}

}  // namespace

std::optional<FieldArrays> structure_arrays_if_solved(const StructureSetup& s, const ContactSolution& solution) {
  if (solution.u.size() != 2L * s.mesh().num_vertices()) return std::nullopt;
  return structure_arrays(s, solution);
}

FieldArrays structure_arrays(const StructureSetup& s, const ContactSolution& solution) {
  const Mesh& ref = s.mesh();
  const Eigen::VectorXd u1 = component(solution.u, 0), u2 = component(solution.u, 1);
  Eigen::VectorXd multiplier = Eigen::VectorXd::Zero(ref.num_vertices());
  Eigen::VectorXd status = Eigen::VectorXd::Zero(ref.num_vertices());
  const auto& rows = s.solver->contact().row_vertex;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    multiplier[rows[i]] = solution.qp.alpha[static_cast<Eigen::Index>(i)];
    status[rows[i]] = solution.qp.active[i] ? 1.0 : 0.0;
  }
  const Eigen::VectorXd magnitude = (u1.array().square() + u2.array().square()).sqrt();
  FieldArrays a;
  a.vertices = ref.vertices;
  a.deformed = displaced(ref, u1, u2).vertices;
  a.fields = {vector_field("displacement", u1, u2), scalar_field("displacement_magnitude", magnitude),
              scalar_field("contact_multiplier", multiplier), scalar_field("contact_status", status)};
  if (const P2Space* p2 = s.p2()) {  // VTK's quadratic triangles on the nodes
    a.cells.resize(p2->mesh().num_triangles(), 6);
    for (int t = 0; t < p2->mesh().num_triangles(); ++t)
      for (int k = 0; k < 6; ++k) a.cells(t, k) = p2->element(t)[k];
    a.fields.push_back(scalar_field("von_mises", von_mises(*p2, s.lame, solution.u), true));
  } else {
    a.cells = triangle_cells(ref);
    a.fields.push_back(scalar_field("von_mises", von_mises(ref, s.lame, solution.u), true));
  }
  return a;
}

FieldArrays fluid_arrays(const Mesh& mesh, const FluidSolution& s, const Eigen::VectorXd& chi) {
  FieldArrays a;
  a.vertices = mesh.vertices;
  a.cells = triangle_cells(mesh);
  const Eigen::VectorXd magnitude = (s.v1.array().square() + s.v2.array().square()).sqrt();
  a.fields = {vector_field("velocity", s.v1, s.v2), scalar_field("velocity_magnitude", magnitude),
              scalar_field("pressure", s.p), scalar_field("chi", chi, true)};
  return a;
}

}  // namespace fsi
