#include "coupling/body_fitted_step.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

Eigen::VectorXd BodyFittedStep::load(const Eigen::VectorXd& u, int k, IterationRecord& rec) {
  pass_ = guarded("the body-fitted fluid step", k, [&] { return fluid_.solve(u); });
  rec.t_mesh = pass_.t_mesh, rec.t_fluid = pass_.t_fluid, rec.t_transfer = pass_.t_transfer;
  rec.fluid_triangles = pass_.mesh->num_triangles(), rec.remeshed = pass_.remeshed;
  return pass_.load;
}

void BodyFittedStep::accept(const ContactSolution& structure, int k) {
  const int active = structure.qp.active_count();
  if (active > 0)
    throw SolverFailure("the body-fitted fluid step failed at fixed-point iteration " + std::to_string(k) +
                        ": the structure touches an obstacle (" + std::to_string(active) +
                        (active == 1 ? " active contact row" : " active contact rows") +
                        "): contact cannot be body-fitted; fluid.method = \"body-fitted\" is a check for "
                        "configurations without contact (use \"penalised\")");
  last_ = std::move(pass_);
}

std::string BodyFittedStep::describe(const IterationRecord& rec) const {
  char line[160];
  std::snprintf(line, sizeof line, "fluid mesh %d triangles (%s) %.3f s  fluid %.3f s  structure %.4f s",
                rec.fluid_triangles, rec.remeshed ? "Gmsh" : "moved", rec.t_mesh, rec.t_fluid, rec.t_structure);
  return line;
}

}  // namespace fsi
