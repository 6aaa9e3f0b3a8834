#include "run/contact_gap.hpp"

namespace fsi {

ContactGap::ContactGap(const Case& c, const StructureSetup& s) : normal_(c.contact.gap == "normal") {
  const ObstacleParams& o = c.obstacle;
  owned_.push_back(std::make_unique<DiskObstacle>(Point(o.x0, o.y0), o.r));
  for (const auto& p : owned_) obstacles_.push_back(p.get());
  const Mesh& mesh = s.mesh();
  // "paper" checks the exact gap on its own rows (Γ_C's interior vertices).
  candidates_ = candidate_vertices(mesh, normal_ ? c.contact.boundary : "Gamma_C", mesh.label("Gamma_C"),
                                   mesh.label("Gamma_D"));
}

ContactSolution ContactGap::solve(StructureSetup& s, const Eigen::VectorXd& b_S, const Eigen::VectorXd& u_start,
                                  const ContactSolution* warm) {
  if (!normal_) {
    linearisations_ = 1;
    return s.solver->solve(b_S, warm);
  }
  RelinearisedContact r = solve_relinearised(*s.solver, candidates_, obstacles_, b_S, u_start);
  linearisations_ = r.linearisations;
  return std::move(r.solution);
}

void ContactGap::relinearise(ElasticContactSolver& solver, const Eigen::VectorXd& u) const {
  solver.set_constraint(assemble_normal_contact(solver.mesh(), candidates_, obstacles_, u));
}

double ContactGap::min_gap(const Mesh& mesh, const Eigen::VectorXd& u) const {
  return min_exact_gap(mesh, candidates_, obstacles_, u);
}

}  // namespace fsi
