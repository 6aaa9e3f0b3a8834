#include "solid/structure_step.hpp"

namespace fsi {

void StructureStep::begin() {
  if (gap_) gap_->relinearise(solver_, Eigen::VectorXd::Zero(2 * solver_.mesh().num_vertices()));
}

ContactSolution StructureStep::solve(const Eigen::VectorXd& b_S, const Eigen::VectorXd& u,
                                     const ContactSolution* warm, double newton_step_tol) {
  if (gap_) gap_->relinearise(solver_, u);
  solver_.newton_step_tol = newton_step_tol;
  struct Reset {  // the solver keeps no tolerance of a pass beyond it
    ElasticContactSolver& s;
    ~Reset() { s.newton_step_tol = 0; }
  } reset{solver_};
  return solver_.solve(b_S, warm);
}

ContactSolution StructureStep::solve_again(const Eigen::VectorXd& b_S, const ContactSolution& from) {
  solver_.newton_step_tol = 0;
  return solver_.solve(b_S, &from);
}

}  // namespace fsi
