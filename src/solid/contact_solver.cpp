#include "solid/contact_solver.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <stdexcept>

namespace fsi {
namespace {

// Columns `keep` of the identity: x_full = P x_free.
SparseMatrix selection(int n_full, const std::vector<int>& keep) {
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t k = 0; k < keep.size(); ++k) t.emplace_back(keep[k], static_cast<int>(k), 1.0);
  SparseMatrix P(n_full, static_cast<int>(keep.size()));
  P.setFromTriplets(t.begin(), t.end());
  return P;
}

// A_S restricted to the free dofs is positive definite iff no rigid motion
// (1,0), (0,1), (−y,x) vanishes on all fixed dofs, i.e. the 3 modes restricted to
// the fixed dofs have rank 3. Checked exactly here because a sparse Cholesky of a
// singular stiffness matrix may "succeed" in floating point and return garbage.
void require_no_rigid_motion(const Mesh& mesh, const std::vector<int>& fixed) {
  const int nv = mesh.num_vertices();
  Eigen::MatrixXd modes(fixed.size(), 3);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Point& p : mesh.vertices) centre += p / nv;
  double scale = 0;
  for (const Point& p : mesh.vertices) scale = std::max(scale, (p - centre).norm());
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    const int v = fixed[k] % nv, c = fixed[k] / nv;
    const Point x = (mesh.vertices[v] - centre) / scale;
    modes(k, 0) = c == 0 ? 1.0 : 0.0;
    modes(k, 1) = c == 1 ? 1.0 : 0.0;
    modes(k, 2) = c == 0 ? -x.y() : x.x();
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(modes);
  qr.setThreshold(1e-10);
  if (fixed.empty() || qr.rank() < 3)
    throw std::invalid_argument(
        "the fixed degrees of freedom do not prevent rigid motion (is Gamma_D a clamped side "
        "with at least two vertices?)");
}

}  // namespace

std::vector<int> clamped_dofs(const Mesh& mesh, int label) {
  return both_components(mesh.vertices_on(label), mesh.num_vertices());
}

ElasticContactSolver::ElasticContactSolver(Mesh mesh, const Lame& lame,
                                           const Foundation& foundation, int gamma_c_label,
                                           const std::vector<int>& fixed_dofs, QpSolver& solver,
                                           std::shared_ptr<const OwnedP2Space> p2, const Inertia* inertia)
    : ElasticContactSolver(Mesh(mesh), lame, assemble_contact(mesh, gamma_c_label, foundation), gamma_c_label,
                           fixed_dofs, solver, std::move(p2), inertia) {}

ElasticContactSolver::ElasticContactSolver(Mesh mesh, const Lame& lame, ContactConstraint contact, int gamma_c_label,
                                           const std::vector<int>& fixed_dofs, QpSolver& solver,
                                           std::shared_ptr<const OwnedP2Space> p2, const Inertia* inertia)
    : mesh_(std::move(mesh)),
      p2_(std::move(p2)),
      gamma_c_label_(gamma_c_label),
      material_{MaterialModel::linear, lame},
      A_S_(p2_ ? assemble_elasticity(p2_->space, lame) : assemble_elasticity(mesh_, lame)),
      contact_(std::move(contact)),
      solver_(solver) {
  if (p2_ && p2_->space.num_nodes() != mesh_.num_vertices())
    throw std::invalid_argument("ElasticContactSolver: the mesh is not the P2 space's nodal mesh");
  const int n = 2 * mesh_.num_vertices();
  std::vector<bool> fixed(n, false);
  for (int d : fixed_dofs) fixed.at(d) = true;
  if (!inertia) require_no_rigid_motion(mesh_, fixed_dofs);
  for (int d = 0; d < n; ++d)
    if (!fixed[d]) free_dofs_.push_back(d);
  P_ = selection(n, free_dofs_);
  A_free_ = P_.transpose() * A_S_ * P_;
  if (inertia) {
    if (inertia->M.rows() != n || inertia->M.cols() != n || !(inertia->c > 0))
      throw std::invalid_argument("ElasticContactSolver: the inertia's mass matrix does not fit the mesh");
    M_free_ = inertia->c * (P_.transpose() * inertia->M * P_);
    A_free_ += M_free_;
  }
  C_free_ = contact_.C_S * P_;
  solver_.set_operator(A_free_, C_free_);
}

void ElasticContactSolver::set_constraint(ContactConstraint contact) {
  if (contact.C_S.cols() != A_S_.rows() || contact.c_lb.size() != contact.C_S.rows())
    throw std::invalid_argument("ElasticContactSolver::set_constraint: sizes do not fit the mesh");
  contact_ = std::move(contact);
  C_free_ = contact_.C_S * P_;
  solver_.set_constraints(C_free_);
}

ContactSolution ElasticContactSolver::solve(const Eigen::VectorXd& b_S,
                                            const ContactSolution* warm) {
  if (material_.model != MaterialModel::linear) return solve_nonlinear(b_S, warm);
  ContactSolution out;
  out.qp = solver_.solve(b_S(free_dofs_), contact_.c_lb, warm ? &warm->qp : nullptr);
  out.u = Eigen::VectorXd::Zero(b_S.size());
  out.u(free_dofs_) = out.qp.x;
  return out;
}

}  // namespace fsi

namespace fsi {

ContactSolution ElasticContactSolver::at_rest() const {
  ContactSolution out;
  const Eigen::Index m = contact_.C_S.rows();
  out.u = Eigen::VectorXd::Zero(A_S_.rows());
  out.qp.x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_dofs_.size()));
  out.qp.alpha = Eigen::VectorXd::Zero(m);
  out.qp.active.assign(static_cast<std::size_t>(m), false);
  out.qp.status = "not solved (at rest)";
  return out;
}

Eigen::VectorXd ElasticContactSolver::project(const Eigen::VectorXd& z) {
  const Eigen::VectorXd slack = contact_.C_S * z - contact_.c_lb;
  if (slack.size() == 0 || slack.minCoeff() >= 0) return z;
  // In the norm of the QP's operator A_free_: A_S, plus c M in a time step. Its load
  // is that operator applied to z: with A_S z alone, a time step's projection
  // shrank z by (A_S + c M)⁻¹ A_S, millimetres off the feasible point next to z
  // (IQN-ILS's updates on paper-7.2-dynamic stalled on it).
  Eigen::VectorXd b = A_S_ * z;
  if (has_inertia()) b(free_dofs_) += M_free_ * z(free_dofs_);
  if (material_.model == MaterialModel::linear) return solve(b).u;
  // The same norm whatever the material: the QP with A_free_, whose operator the next
  // Newton step replaces again.
  solver_.set_operator(A_free_, C_free_);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(z.size());
  u(free_dofs_) = solver_.solve(b(free_dofs_), contact_.c_lb).x;
  return u;
}

std::vector<int> active_vertices(const ElasticContactSolver& solver, const ContactSolution& s) {
  std::vector<int> out;
  const auto& rows = solver.contact().row_vertex;
  for (std::size_t i = 0; i < rows.size() && i < s.qp.active.size(); ++i)
    if (s.qp.active[i]) out.push_back(rows[i]);
  return out;
}

ContactSummary summarize_contact(const ElasticContactSolver& solver, const ContactSolution& s) {
  ContactSummary out;
  const std::vector<int> active = active_vertices(solver, s);
  out.active_nodes = static_cast<int>(active.size());
  if (!active.empty()) {
    out.x_min = out.x_max = solver.mesh().vertices[active[0]].x();
    for (int v : active) {
      out.x_min = std::min(out.x_min, solver.mesh().vertices[v].x());
      out.x_max = std::max(out.x_max, solver.mesh().vertices[v].x());
    }
  }
  out.max_multiplier = s.qp.alpha.size() ? s.qp.alpha.maxCoeff() : 0.0;
  // λ's nodal values: α on the rows' vertices, 0 elsewhere (Γ_C's ends carry no row).
  const Mesh& mesh = solver.mesh();
  std::vector<double> lambda(static_cast<std::size_t>(mesh.num_vertices()), 0.0);
  const auto& rows = solver.contact().row_vertex;
  for (std::size_t i = 0; i < rows.size() && i < static_cast<std::size_t>(s.qp.alpha.size()); ++i)
    lambda[static_cast<std::size_t>(rows[i])] = std::max(s.qp.alpha[static_cast<Eigen::Index>(i)], 0.0);
  double moment = 0;
  // Over every boundary edge: λ vanishes off the rows' vertices, so this is Γ_C's
  // integral for contact.boundary = "Gamma_C", term for term, and the candidates' for "all".
  for (const BoundaryEdge& e : mesh.boundary_edges) {
    const Point &A = mesh.vertices[e.v[0]], &B = mesh.vertices[e.v[1]];
    const double la = lambda[e.v[0]], lb = lambda[e.v[1]], l = (B - A).norm();
    out.pressure_resultant += l * (la + lb) / 2;  // exact: P1 λ, linear X1 on an edge
    moment += l / 6 * (la * (2 * A.x() + B.x()) + lb * (A.x() + 2 * B.x()));
  }
  out.x_centroid = out.pressure_resultant > 0 ? moment / out.pressure_resultant : 0.0;
  return out;
}

}  // namespace fsi
