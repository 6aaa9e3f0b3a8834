// The structure's step of the coupled map (SPEC §5, step 4): for the fluid's load at
// the pass's state u^k, the contact solution ũ^{k+1}, with contact.gap's rule (the
// signed distance re-linearised about u^k, once per pass, SPEC §9; or the paper's
// eq. 15 as built). The coupling (coupling/fixed_point.hpp) composes it with a fluid
// step and does not know which gap or material it holds.
#pragma once

#include <Eigen/Core>

#include "solid/contact_gap.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

class StructureStep {
 public:
  // `gap` null: the constraint stays as the solver holds it.
  explicit StructureStep(ElasticContactSolver& solver, const ContactGap* gap = nullptr)
      : solver_(solver), gap_(gap && gap->normal() ? gap : nullptr) {}

  // A new run (or window) starts from the linearisation at rest, whatever a cached
  // solver's last run left: a sweep's row gives the numbers of a run of its own.
  void begin();
  // ũ for load b_S at the pass's state u, the QP warm-started from `warm` (null: cold).
  // A nonlinear model's Newton stops once a step moves no dof by more than
  // `newton_step_tol` (0: to its full residual tolerance; coupling/fixed_point_loop.hpp).
  // QpError and SolverFailure propagate.
  ContactSolution solve(const Eigen::VectorXd& b_S, const Eigen::VectorXd& u, const ContactSolution* warm,
                        double newton_step_tol);
  // The same pass again (the constraint as the last solve left it), from `from`, to
  // Newton's full tolerance: the state a converged inexact pass reports (SPEC §11).
  ContactSolution solve_again(const Eigen::VectorXd& b_S, const ContactSolution& from);

  // The feasible set's projection (the relaxation's, and a restart's first iterate).
  Eigen::VectorXd project(const Eigen::VectorXd& z) { return solver_.project(z); }
  ContactSolution at_rest() const { return solver_.at_rest(); }
  bool nonlinear() const { return solver_.material().model != MaterialModel::linear; }
  const Mesh& mesh() const { return solver_.mesh(); }
  ElasticContactSolver& solver() { return solver_; }

 private:
  ElasticContactSolver& solver_;
  const ContactGap* gap_;  // null: nothing to re-linearise
};

}  // namespace fsi
