#include "coupling/body_fitted_coupling.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/coupled_map.hpp"
#include "coupling/fixed_point_loop.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

namespace {

// H for the body-fitted fluid: the fluid on the mesh of D \ φ^k(Ω_S0) and its load by
// the residual method (steps 2–3), then the contact QP (step 4), which must find no
// contact.
class BodyFittedMap final : public CoupledMap {
 public:
  BodyFittedMap(const BodyFittedCoupling::Parts& p, BodyFittedStep& last,
                const std::function<void(const Eigen::VectorXd&)>& relinearise)
      : p_(p), last_(last), relinearise_(relinearise) {}

  MapValue operator()(const Eigen::VectorXd& u, int k, const ContactSolution* warm, IterationRecord& rec) override {
    auto fail = [k](const std::string& phase, const std::string& what) {
      throw SolverFailure(phase + " failed at fixed-point iteration " + std::to_string(k) + ": " + what);
    };
    BodyFittedStep fluid = guarded("the body-fitted fluid step", k, [&] { return p_.fluid.solve(u); });
    rec.t_mesh = fluid.t_mesh, rec.t_fluid = fluid.t_fluid, rec.t_transfer = fluid.t_transfer;
    rec.fluid_triangles = fluid.mesh->num_triangles(), rec.remeshed = fluid.remeshed;
    const Eigen::VectorXd b_S = p_.b_applied + fluid.load;
    if (!b_S.allFinite()) fail("the force transfer", "non-finite load on the structure");
    const Stopwatch clock;  // step 4: the contact QP, warm-started
    MapValue value;
    value.structure = guarded("the contact QP", k, [&] {
      if (relinearise_) relinearise_(u);
      return p_.structure.solve(b_S, warm);
    });
    if (!value.structure.u.allFinite()) fail("the contact QP", "non-finite displacement");
    const int active = value.structure.qp.active_count();
    if (active > 0)
      fail("the body-fitted fluid step", "the structure touches an obstacle (" + std::to_string(active) +
                                             (active == 1 ? " active contact row" : " active contact rows") +
                                             "): contact cannot be body-fitted; fluid.method = \"body-fitted\" is a "
                                             "check for configurations without contact (use \"penalised\")");
    value.fluid_load = fluid.load;
    value.load = b_S;
    last_ = std::move(fluid);
    rec.newton_steps = value.structure.newton.steps;
    rec.t_structure = clock.elapsed();
    return value;
  }

  std::string describe(const IterationRecord& rec) const override {
    char line[160];
    std::snprintf(line, sizeof line, "fluid mesh %d triangles (%s) %.3f s  fluid %.3f s  structure %.4f s",
                  rec.fluid_triangles, rec.remeshed ? "Gmsh" : "moved", rec.t_mesh, rec.t_fluid, rec.t_structure);
    return line;
  }

  ElasticContactSolver& structure() override { return p_.structure; }

 private:
  const BodyFittedCoupling::Parts& p_;
  BodyFittedStep& last_;
  const std::function<void(const Eigen::VectorXd&)>& relinearise_;
};

}  // namespace

BodyFittedCoupling::BodyFittedCoupling(Parts parts, double tol, int max_iterations)
    : p_(parts), tol_(tol), max_iterations_(max_iterations), M_(assemble_vector_mass(parts.structure.mesh())) {}

CouplingResult BodyFittedCoupling::run() {
  BodyFittedMap H(p_, last_fluid_, relinearise);
  FixedPointLoop loop(H, p_.relaxation, M_, tol_, max_iterations_);
  loop.progress = progress;
  loop.observe = observe;
  return loop.run(initial);
}

}  // namespace fsi
