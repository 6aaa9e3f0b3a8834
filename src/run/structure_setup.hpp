// Everything about the structure that a run builds once: mesh, material, obstacle,
// A_S and C_S with their QP solver, and the fixed part of the load b_S.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <string>

#include "io/case.hpp"
#include "qp/qp_problem.hpp"
#include "solid/contact_gap.hpp"
#include "solid/contact_solver.hpp"
#include "solid/obstacle.hpp"

namespace fsi {

struct StructureSetup {
 public:
  Lame lame;
  std::shared_ptr<ContactGap> gap;  // contact.gap's rule, obstacles and candidates
  std::unique_ptr<DiskFoundation> foundation;
  std::unique_ptr<QpSolver> qp;
  std::unique_ptr<ElasticContactSolver> solver;
  Eigen::VectorXd b_applied;  // ∫ f_S·w + ∫_{Γ_N} h_S·w (eq. 16)
  // With [time] (SPEC §12): the mass matrix ρ_S M of structure.mass on all dofs, which
  // the solver's operator holds as (4/Δt²) M (Newmark's step); empty otherwise.
  SparseMatrix mass;
  // The mesh the dofs live on: the structure's (P1) or its P2 space's nodal mesh.
  const Mesh& mesh() const { return solver->mesh(); }
  const P2Space* p2() const { return solver->p2(); }  // null with structure.element = "P1"
  // The contact solution under the applied loads alone (eq. 17 with b_applied, no
  // fluid, from the linearisation at rest): fluid.band's box and the fluid's first
  // region hint. Solved once per setup; QpError propagates.
  const ContactSolution& load_alone();

 private:
  std::optional<ContactSolution> load_alone_;
};

// Generates or reads the mesh: a bad user file is an InputError (exit 2), a failure
// to mesh validated geometry a SolverFailure (exit 1). Depends on structure.* and
// obstacle.* only (the sweep caches it by them).
Mesh build_structure_mesh(const Case& c);
// build_structure_mesh, then check_structure_mesh (run/mesh_checks.hpp) against the case.
Mesh make_structure_mesh(const Case& c);

// With structure.element = "P2" the solver's mesh is the nodal mesh of the P2 space on
// `mesh` (fem/p2.hpp): the contact candidates, Γ_D's dofs and the outputs use it.
StructureSetup make_structure(const Case& c, Mesh mesh,
                              const std::function<void(const std::string&)>& progress);

std::unique_ptr<QpSolver> make_qp_solver(const std::string& name);

// b_S's applied part at time t (structure.f may be an expression in t): ∫ f_S·w + ∫_{Γ_N} h_S·w.
Eigen::VectorXd structure_load(const Case& c, const Mesh& mesh, const P2Space* p2, double t);
// structure.v0 at every vertex of `mesh` (the paper's ordering: every x, then every y):
// a time run's initial velocity.
Eigen::VectorXd initial_velocity(const Case& c, const Mesh& mesh);
// Whether structure.f depends on anything (x, y or t): the load is then reassembled per step.
bool structure_load_varies(const Case& c);

// summary.json's contact.gap, min_gap (null without obstacles) and, with "normal",
// obstacles[i].{active_nodes, x_min, x_max, force} (SPEC §9).
void add_gap_summary(nlohmann::ordered_json& contact, const Case& c, const StructureSetup& s, const ContactSolution& solution);

// summary.json's "newton" of a nonlinear structure (SPEC §11): the last solve's Newton
// steps (each one QP), load steps, line-search cuts and final relative residual.
nlohmann::ordered_json newton_json(const NewtonReport& n);

}  // namespace fsi
