// The elastic structure with frictionless contact (SPEC §2): builds A_S and C_S once
// on the reference mesh, eliminates the Dirichlet dofs, and solves the QP for any
// load b_S. The coupling calls solve() once per fixed-point iteration.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fem/p2.hpp"
#include "mesh/mesh.hpp"
#include "qp/qp_problem.hpp"
#include "solid/contact.hpp"
#include "solid/elasticity.hpp"
#include "solid/free_dof_assembly.hpp"
#include "solid/hyperelastic.hpp"
#include "solid/p2_elasticity.hpp"

namespace fsi {

// How Newton's method ended for a nonlinear material (SPEC §11; zeros for "linear").
struct NewtonReport {
  int steps = 0;        // Newton steps (each one QP), over all load steps
  int load_steps = 0;   // 1: the whole load at once; more if Newton alone failed
  int cuts = 0;         // step halvings of the line search
  // The backward error ‖f_int(u) − b − Cᵀα‖∞ / (‖K_T‖∞‖u‖∞ + ‖b‖∞ + ‖Cᵀα‖∞) at the end
  double residual = 0;
  std::vector<double> history;  // that residual after each step (of the last load step)
};

struct ContactSolution {
  Eigen::VectorXd u;       // displacement, 2nv dofs (paper ordering)
  QpResult qp;             // on the free dofs; qp.alpha are the contact multipliers
  NewtonReport newton;
};

// Newmark's step (SPEC §12) adds c·M to the operator: the QP's matrix is A_S + (4/Δt²) M
// (or the tangent + c M), which is positive definite with a free body too (no Γ_D).
struct Inertia {
  SparseMatrix M;  // the mass matrix on all dofs (solid/structure_mass.hpp)
  double c = 0;    // its factor, 4/Δt² for the average acceleration
};

class ElasticContactSolver {
 public:
  // `fixed_dofs`: dofs held at zero (Γ_D); they must prevent every rigid motion
  // (std::invalid_argument otherwise). The mesh is copied; `solver` must outlive this.
  // `p2` (structure.element = "P2"): the operators are P2's on p2->space, and `mesh` is
  // its nodal mesh (nodal_mesh(p2->space), fem/p2.hpp), on which the contact rows, the
  // fixed dofs and every output live as on a P1 mesh (docs/theory.md, "P2").
  ElasticContactSolver(Mesh mesh, const Lame& lame, const Foundation& foundation,
                       int gamma_c_label, const std::vector<int>& fixed_dofs, QpSolver& solver,
                       std::shared_ptr<const OwnedP2Space> p2 = nullptr, const Inertia* inertia = nullptr);

  // The same with a given constraint (contact.gap = "normal": the signed distance's).
  ElasticContactSolver(Mesh mesh, const Lame& lame, ContactConstraint contact, int gamma_c_label,
                       const std::vector<int>& fixed_dofs, QpSolver& solver,
                       std::shared_ptr<const OwnedP2Space> p2 = nullptr, const Inertia* inertia = nullptr);
  // `inertia` (a time step, SPEC §12): the operator is A_S + c M (f_int(u) + c M u for
  // a nonlinear material), and `fixed_dofs` may then be empty (a free body).

  // A nonlinear material (structure.model, SPEC §11): solve() is then Newton's method
  // with the contact constraint in every step, each step one QP with the tangent, to a
  // relative residual `newton_tol`. A_S (the tangent at u = 0) stays the operator of
  // project() and of the relaxation's norm. Call before the first solve.
  void set_material(const Material& material);
  const Material& material() const { return material_; }
  double newton_tol = 1e-10;
  int newton_max_steps = 30;
  // An inexact solve (the coupling's early passes): Newton also stops once a step moves
  // no node by more than this (m), the size of the error it corrects and an upper
  // bound of the error left (quadratic convergence). 0: off, the residual alone decides.
  double newton_step_tol = 0;

  // min ½uᵀA_S u − b_Sᵀu s.t. C_S u ≥ c_lb (linear); the nonlinear equilibrium
  // f_int(u) = b_S + C_Sᵀα with the same constraint (another material). `warm`: an
  // earlier solution, the start of the active set (and of Newton).
  ContactSolution solve(const Eigen::VectorXd& b_S, const ContactSolution* warm = nullptr);

  // The undeformed state u = 0 with no contact (α = 0, no active row): the state
  // before any QP has been solved, complete so that outputs can be written from it.
  ContactSolution at_rest() const;

  // Replaces the contact constraint (contact.gap = "normal": C_S, c_lb re-linearised
  // about a new state); A_S and its factorisation are kept.
  void set_constraint(ContactConstraint contact);

  // The feasible displacement nearest to z in the norm of the operator K = A_S (+ c M
  // with inertia): z itself if C_S z ≥ c_lb, otherwise the QP with load K z
  // (min ½(ξ−z)ᵀK(ξ−z) s.t. C_S ξ ≥ c_lb).
  Eigen::VectorXd project(const Eigen::VectorXd& z);

  const SparseMatrix& A_S() const { return A_S_; }
  // The free dofs (increasing): the rest are held at zero.
  const std::vector<int>& free_dofs() const { return free_dofs_; }
  bool has_inertia() const { return M_free_.size() > 0; }
  const ContactConstraint& contact() const { return contact_; }
  // The mesh the dofs live on: the structure's mesh (P1), or the P2 space's nodal mesh.
  const Mesh& mesh() const { return mesh_; }
  const P2Space* p2() const { return p2_ ? &p2_->space : nullptr; }
  const std::shared_ptr<const OwnedP2Space>& p2_space() const { return p2_; }
  int gamma_c_label() const { return gamma_c_label_; }
  QpSolver& qp_solver() { return solver_; }

 private:
  ContactSolution solve_nonlinear(const Eigen::VectorXd& b_S, const ContactSolution* warm);
  void require_unfolded(const Eigen::VectorXd& u) const;
  Eigen::VectorXd force(const Eigen::VectorXd& u) const;  // f_int(u) (+ c M u) on the free dofs
  bool newton(const Eigen::VectorXd& b_S, ContactSolution& state, NewtonReport& report);
  // A Newton step taken: the displacement, its internal force and equilibrium
  // residual, and how many times it was halved.
  struct DampedStep {
    Eigen::VectorXd u, f;
    double residual;
    int cuts;
  };
  bool solve_step_qp(const Eigen::VectorXd& b, const Eigen::VectorXd& f, const Eigen::VectorXd& x_k,
                     const QpResult* warm, QpResult& qp);
  DampedStep damped_step(const Eigen::VectorXd& u, const Eigen::VectorXd& x_k, const QpResult& qp,
                         const Eigen::VectorXd& b, double K_norm, double r_prev);
  double equilibrium_residual(const Eigen::VectorXd& f, const Eigen::VectorXd& b, const Eigen::VectorXd& alpha,
                              const Eigen::VectorXd& x, double K_norm) const;

  Mesh mesh_;
  std::shared_ptr<const OwnedP2Space> p2_;
  int gamma_c_label_;
  Material material_;
  std::string last_newton_failure_;  // the QP's words when a Newton step failed
  std::unique_ptr<FreeDofAssembler> assembler_;  // a nonlinear material's f_int and K_T
  SparseMatrix K_;                                // the tangent (A_free_'s pattern)
  SparseMatrix A_S_;
  ContactConstraint contact_;
  std::vector<int> free_dofs_;
  SparseMatrix P_;  // free dofs → all dofs
  SparseMatrix A_free_, C_free_;
  SparseMatrix M_free_;  // c M on the free dofs (empty without inertia)
  QpSolver& solver_;
};

// Both components of every vertex on `label` (a clamped side).
std::vector<int> clamped_dofs(const Mesh& mesh, int label);

}  // namespace fsi

namespace fsi {

// What summary.json reports of a contact state (SPEC §8).
struct ContactSummary {
  int active_nodes = 0;
  double x_min = 0, x_max = 0;  // reference X1 extent of the active vertices (if any)
  double max_multiplier = 0;    // largest α: peak discrete contact pressure
  // The contact pressure λ = Σ α_i φ_i on the candidate boundary (the multipliers of
  // eq. 21's rows are its nodal values), integrated exactly on its edges: ∫ λ ds (N/m)
  // and the reference X1 of its centroid ∫ λ X1 ds / ∫ λ ds. Unlike x_min, x_max,
  // which jump from vertex to vertex, the centroid moves continuously with the mesh:
  // the contact point a refinement study can converge.
  double pressure_resultant = 0;
  double x_centroid = 0;
};
ContactSummary summarize_contact(const ElasticContactSolver& solver, const ContactSolution& s);

// Mesh vertices whose contact row is active.
std::vector<int> active_vertices(const ElasticContactSolver& solver, const ContactSolution& s);

}  // namespace fsi
