// Newmark's average acceleration (β = 1/4, γ = 1/2; SPEC §12) for the structure with
// frictionless contact at the new time:
//     M a^{n+1} + f_int(u^{n+1}) = b^{n+1} + C_Sᵀ α^{n+1},   C_S u^{n+1} ≥ c_lb (complementary α),
//     u^{n+1} = u^n + Δt v^n + Δt²/4 (a^n + a^{n+1}),   v^{n+1} = v^n + Δt/2 (a^n + a^{n+1}).
// Eliminating a^{n+1} = (4/Δt²)(u^{n+1} − u^n − Δt v^n) − a^n, each step is the
// ElasticContactSolver's contact problem with the operator A_S + (4/Δt²) M (its
// Inertia) and the load
//     b_eff = b^{n+1} + M [(4/Δt²)(u^n + Δt v^n) + a^n]            (effective_load),
// one QP per step (per Newton step for a nonlinear material). Without contact and
// for a linear material the scheme keeps ½vᵀMv + ½uᵀA_S u − work exactly (to
// round-off) and is of order 2. This class holds the scheme's arithmetic; who solves
// the step's contact problem (ContactGap::solve, the coupling) is the caller.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "mesh/mesh.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

struct NewmarkState {
  int step = 0;
  double t = 0;
  Eigen::VectorXd u, v, a;  // all dofs; zero on the fixed ones
  ContactSolution contact;  // the step's contact solution (u and its multipliers)
};

class Newmark {
 public:
  // `M`: the mass matrix on all dofs (ρ included); `free_dofs`: the solver's.
  Newmark(SparseMatrix M, double dt, std::vector<int> free_dofs);
  // The factor of M in the step's operator: 4/Δt².
  static double operator_factor(double dt) { return 4.0 / (dt * dt); }
  double dt() const { return dt_; }

  // The state at t0 from u0, v0 (both on all dofs; zeroed on the fixed ones) and the
  // force r0 = b(t0) − f_int(u0) (+ C_Sᵀα0): a0 solves M a0 = r0 on the dofs that carry
  // mass; a massless dof (mass redistribution) has a0 = 0, its equation being static.
  NewmarkState start(double t0, Eigen::VectorXd u0, Eigen::VectorXd v0, const Eigen::VectorXd& r0,
                     ContactSolution contact);
  // b_eff of the step from `s` for the load b^{n+1}.
  Eigen::VectorXd effective_load(const NewmarkState& s, const Eigen::VectorXd& b_next) const;
  // The state at t^{n+1} = t0 + (n + 1)Δt (not a sum of Δt's: no drift) from the
  // step's contact solution (its u is u^{n+1}).
  NewmarkState advance(const NewmarkState& s, ContactSolution next) const;

  double kinetic_energy(const Eigen::VectorXd& v) const { return 0.5 * v.dot(M_ * v); }
  // Σ_i (M v)_i per component: the momentum, and with v = 1 the mass (nv nodes).
  Point momentum(const Eigen::VectorXd& v) const;
  double mass() const { return mass_; }
  const SparseMatrix& M() const { return M_; }

 private:
  SparseMatrix M_;
  double dt_;
  double t0_ = 0;
  std::vector<int> free_dofs_;
  double mass_ = 0;
};

// The elastic energy at u: ½uᵀA_S u for the linear model, ∫ W(F(u)) otherwise (P1 and P2).
double elastic_energy(const ElasticContactSolver& solver, const Eigen::VectorXd& u);

}  // namespace fsi
