#include "solid/contact_gap.hpp"

#include <algorithm>

namespace fsi {

ContactGap::ContactGap(std::vector<std::unique_ptr<Obstacle>> obstacles, bool normal, const Mesh& mesh,
                       const std::string& boundary)
    : normal_(normal), owned_(std::move(obstacles)) {
  for (const auto& p : owned_) obstacles_.push_back(p.get());
  // "paper" checks the exact gap on its own rows (Γ_C's interior vertices); with no
  // obstacle (obstacles = []) there is nothing to touch and no row.
  if (obstacles_.empty()) return;
  candidates_ = candidate_vertices(mesh, normal_ ? boundary : "Gamma_C", mesh.label("Gamma_C"), mesh.label("Gamma_D"));
}

ContactConstraint ContactGap::at_rest(const Mesh& mesh) const {
  return assemble_normal_contact(mesh, candidates_, obstacles_, Eigen::VectorXd::Zero(2 * mesh.num_vertices()));
}

ContactSolution ContactGap::solve(ElasticContactSolver& solver, const Eigen::VectorXd& b_S,
                                  const Eigen::VectorXd& u_start, const ContactSolution* warm) {
  if (!normal_) {
    linearisations_ = 1;
    return solver.solve(b_S, warm);
  }
  RelinearisedContact r = solve_relinearised(solver, candidates_, obstacles_, b_S, u_start);
  linearisations_ = r.linearisations;
  return std::move(r.solution);
}

void ContactGap::relinearise(ElasticContactSolver& solver, const Eigen::VectorXd& u) const {
  solver.set_constraint(assemble_normal_contact(solver.mesh(), candidates_, obstacles_, u));
}

double ContactGap::min_gap(const Mesh& mesh, const Eigen::VectorXd& u, bool all_vertices) const {
  if (obstacles_.empty()) return INFINITY;
  if (!all_vertices) return min_exact_gap(mesh, candidates_, obstacles_, u);
  CandidateSet every;
  for (int v = 0; v < mesh.num_vertices(); ++v) every.vertices.push_back(v), every.weights.push_back(1);
  return min_exact_gap(mesh, every, obstacles_, u);
}

std::vector<ContactGap::PerObstacle> ContactGap::per_obstacle(const ElasticContactSolver& solver,
                                                              const ContactSolution& s) const {
  std::vector<PerObstacle> out(obstacles_.size());
  if (!normal_) return out;
  const Mesh& mesh = solver.mesh();
  const int nv = mesh.num_vertices();
  const auto& rows = solver.contact().row_vertex;
  for (std::size_t i = 0; i < rows.size() && i < s.qp.active.size(); ++i) {
    const int v = rows[i];
    const Point x = mesh.vertices[v] + Point(s.u[v], s.u[nv + v]);
    const NearestObstacle n = nearest(obstacles_, x);
    if (n.index < 0) continue;
    PerObstacle& o = out[static_cast<std::size_t>(n.index)];
    // Row i is w_i n·u ≥ ...: its reaction on the structure is α_i w_i n (the row's coefficients).
    const double fx = solver.contact().C_S.coeff(static_cast<Eigen::Index>(i), v),
                 fy = solver.contact().C_S.coeff(static_cast<Eigen::Index>(i), nv + v);
    o.force += s.qp.alpha[static_cast<Eigen::Index>(i)] * Point(fx, fy);
    if (!s.qp.active[i]) continue;
    const double X = mesh.vertices[v].x();
    o.x_min = o.active_nodes ? std::min(o.x_min, X) : X;
    o.x_max = o.active_nodes ? std::max(o.x_max, X) : X;
    ++o.active_nodes;
  }
  return out;
}

}  // namespace fsi
