// contact.gap for a run (SPEC §9): the paper's eq. (15), or the signed distance
// re-linearised about the current state (solid/relinearised_contact.hpp), with the
// obstacles and the candidate vertices the case asks for; and the exact gap that
// summary.json reports for either rule (contact.min_gap).
#pragma once

#include <memory>
#include <vector>

#include "io/case.hpp"
#include "run/structure_setup.hpp"
#include "solid/relinearised_contact.hpp"
#include "solid/signed_distance.hpp"

namespace fsi {

class ContactGap {
 public:
  ContactGap(const Case& c, const StructureSetup& s);

  bool normal() const { return normal_; }
  // The contact solution for load b_S: one QP ("paper"), or re-linearised QPs from
  // u_start ("normal"; empty: from rest). QpError and SolverFailure propagate.
  ContactSolution solve(StructureSetup& s, const Eigen::VectorXd& b_S, const Eigen::VectorXd& u_start = {},
                        const ContactSolution* warm = nullptr);
  // The exact signed distance's minimum over the candidates at u (m; negative: the
  // structure penetrates an obstacle).
  double min_gap(const Mesh& mesh, const Eigen::VectorXd& u) const;
  int linearisations() const { return linearisations_; }
  // "normal": the constraint of `solver` linearised about u (a coupled run's pass).
  void relinearise(ElasticContactSolver& solver, const Eigen::VectorXd& u) const;

 private:
  bool normal_;
  std::vector<std::unique_ptr<Obstacle>> owned_;
  std::vector<const Obstacle*> obstacles_;
  CandidateSet candidates_;
  int linearisations_ = 0;
};

}  // namespace fsi
