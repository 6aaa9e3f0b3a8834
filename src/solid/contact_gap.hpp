// The structure's gap to its obstacles (SPEC §9): the paper's eq. (15), or the signed
// distance re-linearised about the current state (solid/relinearised_contact.hpp), with
// the obstacles and the candidate vertices; and the exact gap that summary.json
// reports for either rule. The run builds it from the case (case_contact_gap,
// run/case_contact.hpp).
#pragma once

#include <memory>
#include <vector>

#include <string>
#include "solid/contact_solver.hpp"
#include "solid/relinearised_contact.hpp"
#include "solid/signed_distance.hpp"

namespace fsi {

// Polygons are held off by this fraction of diam(Ω_S0) (solid/signed_distance.hpp),
// 1000 times the stopping tolerance. Measured (a beam onto a block's corner and a
// wedge's tip): at 1e-7 both QP solvers settle in 3 passes and agree to 1e-10
// relative; at 1e-8 IPOPT's solutions (accurate to ~1e-9 m there) kept the wedge's
// passes from settling. Max |u| moves by 2e-6 relative from 1e-8 to 1e-7.
inline constexpr double kPolygonMargin = 1e-7;

class ContactGap {
 public:
  // `mesh`: the structure's reference mesh (labels Gamma_C, Gamma_D). `normal`: the
  // signed distance re-linearised (contact.gap = "normal"), its candidates on
  // `boundary` (contact.boundary); else eq. (15) on Γ_C's interior vertices. No
  // obstacle: nothing to touch and no row.
  ContactGap(std::vector<std::unique_ptr<Obstacle>> obstacles, bool normal, const Mesh& mesh,
             const std::string& boundary);

  bool normal() const { return normal_; }
  // "normal": the constraint linearised at rest (the structure's first constraint).
  ContactConstraint at_rest(const Mesh& mesh) const;
  // The contact solution for load b_S: one QP ("paper"), or re-linearised QPs from
  // u_start ("normal"; empty: from rest). QpError and SolverFailure propagate.
  ContactSolution solve(ElasticContactSolver& solver, const Eigen::VectorXd& b_S, const Eigen::VectorXd& u_start = {},
                        const ContactSolution* warm = nullptr);
  // "normal": the constraint of `solver` linearised about u (a coupled run's pass).
  void relinearise(ElasticContactSolver& solver, const Eigen::VectorXd& u) const;
  // The exact signed distance's minimum over the candidates at u (m; negative: the
  // structure penetrates an obstacle).
  // all_vertices: over every vertex instead (the structure at rest inside an obstacle).
  double min_gap(const Mesh& mesh, const Eigen::VectorXd& u, bool all_vertices = false) const;
  int linearisations() const { return linearisations_; }

  // Per obstacle, in the case's order: the active rows nearest to it, their reference
  // X1 extent and the contact reaction Σ α_i w_i n_i on the structure (N/m).
  struct PerObstacle {
    int active_nodes = 0;
    double x_min = 0, x_max = 0;
    Point force = Point::Zero();
  };
  std::vector<PerObstacle> per_obstacle(const ElasticContactSolver& solver, const ContactSolution& s) const;
  std::size_t count() const { return obstacles_.size(); }

 private:
  bool normal_;
  std::vector<std::unique_ptr<Obstacle>> owned_;
  std::vector<const Obstacle*> obstacles_;
  CandidateSet candidates_;
  int linearisations_ = 0;
};

}  // namespace fsi
