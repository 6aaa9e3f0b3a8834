#include "coupling/body_fitted_coupling.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "coupling/pass_steps.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

BodyFittedCoupling::BodyFittedCoupling(Parts parts, double tol, int max_iterations)
    : p_(parts),
      tol_(tol),
      max_iterations_(max_iterations),
      M_(assemble_vector_mass(parts.structure.mesh())) {
  p_.relaxation.project = [this](const Eigen::VectorXd& z) { return p_.structure.project(z); };
}

CouplingResult BodyFittedCoupling::run() {
  CouplingResult result;
  result.structure = p_.structure.at_rest();
  try {
    iterate(result);
  } catch (const SolverFailure& e) {
    result.failure = e.what();
  }
  result.projections = p_.relaxation.projections();
  return result;
}

void BodyFittedCoupling::iterate(CouplingResult& result) {
  Eigen::VectorXd u = initial_iterate(p_.structure, initial);
  const ContactSolution* warm = nullptr;
  auto fail = [&](const std::string& phase, const std::string& what) {
    throw SolverFailure(phase + " failed at fixed-point iteration " +
                        std::to_string(result.iterations) + ": " + what);
  };
  for (int k = 1; k <= max_iterations_; ++k) {
    result.iterations = k;
    IterationRecord rec;
    rec.iteration = k;
    // Steps 2–3: the fluid on the mesh of D \ φ^k(Ω_S0) and its load on the structure.
    BodyFittedStep fluid =
        guarded("the body-fitted fluid step", k, [&] { return p_.fluid.solve(u); });
    rec.t_mesh = fluid.t_mesh, rec.t_fluid = fluid.t_fluid, rec.t_transfer = fluid.t_transfer;
    rec.fluid_triangles = fluid.mesh->num_triangles(), rec.remeshed = fluid.remeshed;
    const Eigen::VectorXd b_S = p_.b_applied + fluid.load;
    if (!b_S.allFinite()) fail("the force transfer", "non-finite load on the structure");
    {
      const Stopwatch clock;  // step 4: the contact QP, warm-started
      ContactSolution next =
          guarded("the contact QP", k, [&] { return p_.structure.solve(b_S, warm); });
      if (!next.u.allFinite()) fail("the contact QP", "non-finite displacement");
      if (next.qp.active_count() > 0)
        fail("the body-fitted fluid step",
             "the structure touches the obstacle (" + std::to_string(next.qp.active_count()) +
                 (next.qp.active_count() == 1 ? " active contact row" : " active contact rows") + "): contact cannot be body-fitted; fluid.method = "
                 "\"body-fitted\" is a check "
                 "for configurations without contact (use \"penalised\")");
      result.structure = std::move(next);
      result.fluid_load = fluid.load;
      last_fluid_ = std::move(fluid);
      rec.t_structure = clock.elapsed();
    }
    const Eigen::VectorXd d = result.structure.u - u;  // step 5
    rec.increment = std::sqrt(d.dot(M_ * d));
    if (!std::isfinite(rec.increment))
      fail("the stopping test", "the increment is not a finite number");
    result.final_increment = rec.increment;
    result.final_norm = std::sqrt(result.structure.u.dot(M_ * result.structure.u));
    const bool converged = rec.increment < tol_;
    result.history.push_back(rec);
    if (!converged && k < max_iterations_) {
      u = relaxed_iterate(p_.relaxation, u, result.structure.u, k, rec, result);
    }
    if (progress) {
      char omega[16] = "-";
      if (std::isfinite(rec.omega)) std::snprintf(omega, sizeof omega, "%.3g", rec.omega);
      char line[256];
      std::snprintf(line, sizeof line,
                    "[coupling] it %3d: increment %.4e  omega %-6s fluid mesh %d triangles (%s) "
                    "%.3f s  fluid %.3f s  "
                    "structure %.4f s",
                    k, rec.increment, omega, rec.fluid_triangles, rec.remeshed ? "Gmsh" : "moved",
                    rec.t_mesh, rec.t_fluid, rec.t_structure);
      progress(line);
    }
    if (converged) {
      result.converged = true;
      return;
    }
    if (interrupt_requested()) {
      result.interrupted = true;
      if (progress)
        progress("[coupling] interrupted (Ctrl-C): stopping after iteration " + std::to_string(k));
      return;
    }
    warm = &result.structure;
  }
}

}  // namespace fsi
