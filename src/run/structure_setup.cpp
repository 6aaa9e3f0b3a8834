#include "run/structure_setup.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/case_contact.hpp"
#include "run/case_fields.hpp"
#include "run/mesh_checks.hpp"
#include "solid/newmark.hpp"
#include "solid/p2_elasticity.hpp"
#include "solid/structure_mass.hpp"
#include "qp/active_set_solver.hpp"
#include "qp/ipopt_solver.hpp"

namespace fsi {

std::unique_ptr<QpSolver> make_qp_solver(const std::string& name) {
  if (name == "ipopt") return std::make_unique<IpoptSolver>();
  return std::make_unique<ActiveSetSolver>();
}

Mesh build_structure_mesh(const Case& c) {
  const auto& s = c.structure;
  const auto& o = c.obstacle;
  if (s.rectangle()) {
    try {
      // With [[obstacles]] Gamma_C is only a label (contact.boundary = "all"): the
      // bottom's middle third.
      const double xc0 = c.obstacles_given ? s.L / 3 : o.xc_min(), xc1 = c.obstacles_given ? 2 * s.L / 3 : o.xc_max();
      return generate_structure_mesh({s.L, s.H, xc0, xc1, s.h}, mesh_generator(s.mesher));
    } catch (const MeshError& e) {  // the geometry was validated: the generator's failure
      throw SolverFailure(std::string("meshing the structure failed: ") + e.what());
    }
  }
  // SPEC §9: Gamma_D and Gamma_N required, Gamma_C optional (the candidate edges of
  // contact.boundary = "all" need none); a mesh file of §8 has all three.
  // P2: four nodal-mesh triangles a triangle (as the check of structure.h).
  const double limit = case_limits().structure_triangles / (s.element == "P2" ? 4 : 1);
  if (s.shape == "geo") {
    try {
      return mesh_geo_script(s.geo, s.h, limit, {"Gamma_D", "Gamma_N"}, {"Gamma_C"}, "Omega_S");
    } catch (const MeshError& e) {  // the script is the user's: its failure is an input error
      throw InputError(c.source + ": structure.geo: " + e.what());
    }
  }
  return read_case_mesh(c, "structure.mesh", s.mesh, {"Gamma_D", "Gamma_N"}, "Omega_S", limit, {"Gamma_C"});
}

namespace {

// structure.clamped = false (SPEC §12, a free body): Γ_D's edges become Γ_N's, free
// and loaded by h_N; the label stays, with no edge, so that no dof is held.
void free_gamma_d(Mesh& mesh) {
  if (!mesh.has_label("Gamma_D")) return;
  const int d = mesh.label("Gamma_D"), n = mesh.add_label("Gamma_N");
  for (BoundaryEdge& e : mesh.boundary_edges)
    if (e.label == d) e.label = n;
}

}  // namespace

Mesh make_structure_mesh(const Case& c) {
  Mesh mesh = build_structure_mesh(c);
  if (!c.structure.clamped) free_gamma_d(mesh);
  check_structure_mesh(c, mesh);
  return mesh;
}

namespace {

// ∫ f_S·w + ∫_{Γ_N} h_S·w for constant f_S, h_N: exact with one point (P1) and with the
// P2 space's degree-2 triangle and 2-point edge rules. An f_S that varies (an
// expression, SPEC §10) takes the degree-4 rule: exact for its quadratic part on P2.
Eigen::VectorXd applied_load(const Case& c, const Mesh& mesh, const P2Space* p2, double t = kSteadyTime) {
  const Point h_N = c.structure.h_N;
  const VectorField f_S = structure_body_force(c.structure, t);
  const auto h_S = [h_N](const Point&) { return h_N; };
  const int gamma_n = mesh.label("Gamma_N");
  const bool varies = body_force_varies(c.structure);
  if (p2) return assemble_volume_load(*p2, f_S, varies ? 4 : 2) + assemble_surface_load(*p2, gamma_n, h_S, 2);
  return assemble_volume_load(mesh, f_S, varies ? 4 : 1) + assemble_surface_load(mesh, gamma_n, h_S, 1);
}

// The mass matrix of structure.mass: redistributed off the contact rows' vertices.
SparseMatrix structure_mass(const Case& c, const Mesh& mesh, const P2Space* p2, const ContactConstraint& contact) {
  if (c.structure.mass == "consistent") return consistent_mass(mesh, p2, c.structure.rho);
  std::vector<int> rows = contact.row_vertex;
  return redistributed_mass(mesh, rows, c.structure.rho);
}

}  // namespace

Eigen::VectorXd structure_load(const Case& c, const Mesh& mesh, const P2Space* p2, double t) {
  return applied_load(c, mesh, p2, t);
}

Eigen::VectorXd initial_velocity(const Case& c, const Mesh& mesh) {
  const int n = mesh.num_vertices();
  Eigen::VectorXd v0(2 * n);
  v0 << Eigen::VectorXd::Constant(n, c.structure.v0.x()), Eigen::VectorXd::Constant(n, c.structure.v0.y());
  return v0;
}

bool structure_load_varies(const Case& c) {
  return !c.structure.f_expression[0].empty() || !c.structure.f_expression[1].empty();
}

const ContactSolution& StructureSetup::load_alone() {
  if (!load_alone_) {
    // From rest, whatever a cached setup's last coupled run left in the constraint.
    if (gap->normal()) gap->relinearise(*solver, Eigen::VectorXd::Zero(2 * mesh().num_vertices()));
    load_alone_ = solver->solve(b_applied);
  }
  return *load_alone_;
}

StructureSetup make_structure(const Case& c, Mesh mesh,
                              const std::function<void(const std::string&)>& progress) {
  StructureSetup s;
  s.lame = Lame::from_young_poisson(c.structure.E, c.structure.nu);
  s.foundation = std::make_unique<DiskFoundation>(c.obstacle.x0, c.obstacle.y0, c.obstacle.r);
  s.qp = make_qp_solver(c.contact.solver);
  s.qp->progress = progress;
  std::shared_ptr<const OwnedP2Space> p2;
  if (c.structure.element == "P2") {
    p2 = std::make_shared<const OwnedP2Space>(std::move(mesh));
    mesh = nodal_mesh(p2->space);
  }
  const int gamma_c = mesh.label("Gamma_C");
  const std::vector<int> fixed = clamped_dofs(mesh, mesh.label("Gamma_D"));
  s.gap = std::make_shared<ContactGap>(case_contact_gap(c, mesh));
  // "normal": its first constraint linearised at rest (no ψ: the obstacles need not be the paper's disk).
  ContactConstraint first = s.gap->normal() ? s.gap->at_rest(mesh) : assemble_contact(mesh, gamma_c, *s.foundation);
  std::optional<Inertia> inertia;
  if (c.time) {  // Newmark's operator A_S + (4/Δt²) M (SPEC §12)
    s.mass = structure_mass(c, p2 ? p2->mesh : mesh, p2 ? &p2->space : nullptr, first);
    inertia = Inertia{s.mass, Newmark::operator_factor(c.time->dt)};
  }
  try {
    s.solver = std::make_unique<ElasticContactSolver>(std::move(mesh), s.lame, std::move(first), gamma_c, fixed, *s.qp,
                                                      p2, inertia ? &*inertia : nullptr);
  } catch (const QpError& e) {
    // A free body rests on its mass alone: (4/Δt²)M lost against A_S in double precision.
    const std::string free_body = c.structure.clamped ? "" : "; a free body (structure.clamped = false) rests on "
        "its mass term (4/Δt²) ρ_S h², here lost against E in double precision: a larger structure.rho or a smaller time.dt";
    throw SolverFailure(std::string("structure: ") + e.what() + free_body);
  }
  if (c.structure.model != "linear") s.solver->set_material({material_model(c.structure.model), s.lame});
  s.b_applied = applied_load(c, s.mesh(), s.p2());
  return s;
}

void add_gap_summary(nlohmann::ordered_json& contact, const Case& c, const StructureSetup& s,
                     const ContactSolution& solution) {
  contact["gap"] = c.contact.gap;
  const double g = s.gap->min_gap(s.mesh(), solution.u);
  contact["min_gap"] = std::isfinite(g) ? nlohmann::ordered_json(g) : nlohmann::ordered_json(nullptr);
  if (!s.gap->normal()) return;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ContactGap::PerObstacle& o : s.gap->per_obstacle(*s.solver, solution)) {
    nlohmann::ordered_json e = {{"active_nodes", o.active_nodes}};
    e["x_min"] = o.active_nodes ? nlohmann::ordered_json(o.x_min) : nlohmann::ordered_json(nullptr);
    e["x_max"] = o.active_nodes ? nlohmann::ordered_json(o.x_max) : nlohmann::ordered_json(nullptr);
    e["force"] = {o.force.x(), o.force.y()};
    list.push_back(e);
  }
  contact["obstacles"] = list;
}

nlohmann::ordered_json newton_json(const NewtonReport& n) {
  return {{"steps", n.steps}, {"load_steps", n.load_steps}, {"cuts", n.cuts}, {"residual", n.residual},
          {"residual_history", n.history}};
}

}  // namespace fsi
