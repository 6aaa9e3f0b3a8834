#include "run/fluid_march.hpp"

#include <optional>

#include "common/errors.hpp"
#include "run/fluid_setup.hpp"
#include "run/outputs/obstacle_forces.hpp"
#include "run/taylor_hood_setup.hpp"
#include "run/time_checkpoint.hpp"

namespace fsi {
namespace {

SolverFailure steady_failure(const SolverFailure& e) {
  return SolverFailure(std::string("the steady flow at t = 0 (time.start_from = \"steady\"): ") + e.what());
}

// The mini element: FluidTimeStepper on the penalised system with χ = 0.
class MiniMarch final : public FluidMarch {
 public:
  MiniMarch(const Case& c, Mesh mesh) : c_(c), time_(*c.time), f_(make_fluid(c, std::move(mesh), c.coupling.eps)) {
    f_.stokes->set_chi(Eigen::VectorXd::Zero(f_.mesh->num_triangles()));  // no structure
  }
  const Mesh& mesh() const override { return *f_.mesh; }

  void start(bool steady) override {
    // The steady flow first, before the stepper adds the time derivative to the operator.
    const FluidSolution initial = steady && !restored_ ? steady_flow() : fluid_at_rest(*f_.mesh);
    stepper_ = std::make_unique<FluidTimeStepper>(*f_.stokes, c_.fluid->rho, time_scheme(time_), time_.dt, initial);
    if (!restored_) return;
    stepper_->restore(restored_->step, restored_->v_n, restored_->v_nm1);
    if (restored_->step > 0) f_.stokes->start_from(restored_->v_n);  // Newton's next start
    restored_.reset();
  }
  void step() override {
    stepper_->step([&](double t) { data(t); });
  }
  const FluidSolution& state() const override { return stepper_->state(); }
  double time() const override { return stepper_->time(); }
  int steps() const override { return stepper_->steps(); }
  int newton_steps() const override {
    const FluidNewtonReport* n = f_.stokes->newton();
    return n ? n->steps + n->picard_steps : 0;
  }
  bool navier_stokes() const override { return f_.stokes->newton() != nullptr; }

  std::vector<Point> forces() override {
    MomentumModel model = momentum_model(*c_.fluid);
    model.inertia = stepper_->last_step_inertia();
    const VectorField f = fluid_body_force(*c_.fluid, time());
    std::vector<Point> out;
    for (const std::string& hole : obstacle_hole_names(c_))
      out.push_back(hole_force(*f_.mesh, model, f, state(), f_.mesh->label(hole), {}));
    return out;
  }
  Json probes() const override { return fluid_probes_json(c_, *f_.mesh, &state()); }
  Json json() const override { return fluid_json(*f_.stokes); }
  void save(Checkpoint& k) const override {
    put_fluid(k, "v_n", stepper_->state());
    put_fluid(k, "v_nm1", stepper_->previous());
  }
  void restore(const Checkpoint& k) override {
    const int nv = f_.mesh->num_vertices(), nt = f_.mesh->num_triangles();
    restored_ = Restored{k.step, get_fluid(k, "v_n", nv, nt), get_fluid(k, "v_nm1", nv, nt)};
  }

 private:
  void data(double t) {
    f_.stokes->set_body_force(fluid_body_force(*c_.fluid, t));
    f_.stokes->set_boundary_data(box_boundary_conditions(*f_.mesh, *c_.fluid, t));
  }
  FluidSolution steady_flow() {
    data(0.0);
    try {
      FluidSolution v = f_.stokes->solve();
      v.exact_on = nullptr;
      return v;
    } catch (const SolverFailure& e) {
      throw steady_failure(e);
    }
  }

  const Case& c_;
  const TimeParams& time_;
  FluidSetup f_;
  std::unique_ptr<FluidTimeStepper> stepper_;
  struct Restored {
    int step;
    FluidSolution v_n, v_nm1;
  };
  std::optional<Restored> restored_;  // a checkpoint's state, until start() gives it to the stepper
};

// Taylor–Hood: TaylorHoodFlow's BDF steps; the state shown at the vertices.
class TaylorHoodMarch final : public FluidMarch {
 public:
  TaylorHoodMarch(const Case& c, Mesh mesh) : c_(c), time_(*c.time), s_(make_taylor_hood(c, std::move(mesh))) {}
  const Mesh& mesh() const override { return *s_.mesh; }

  void start(bool steady) override {
    Eigen::VectorXd initial = Eigen::VectorXd::Zero(s_.system->dofs());
    if (steady && !restored_) {
      try {
        initial = s_.flow->solve();
      } catch (const SolverFailure& e) {
        throw steady_failure(e);
      }
    }
    s_.flow->start(c_.fluid->rho, time_scheme(time_), time_.dt, initial);
    if (restored_) {
      s_.flow->restore(restored_->step, restored_->u_n, restored_->u_nm1);
      if (restored_->factors_at.size()) s_.flow->restore_factors(restored_->factors_at, restored_->factors_mass);
      restored_.reset();
    }
    view_ = s_.flow->vertex_view();
  }
  void step() override {
    s_.flow->step([&](double t) { set_taylor_hood_data(s_, c_, t); });
    view_ = s_.flow->vertex_view();
  }
  const FluidSolution& state() const override { return view_; }
  double time() const override { return s_.flow->time(); }
  int steps() const override { return s_.flow->steps(); }
  int newton_steps() const override { return navier_stokes() ? s_.flow->report().steps : 0; }
  bool navier_stokes() const override { return s_.system->model().rho > 0; }
  std::vector<Point> forces() override { return taylor_hood_hole_forces(s_, c_); }
  Json probes() const override { return taylor_hood_probes_json(c_, s_); }
  Json json() const override { return taylor_hood_json(s_); }
  void save(Checkpoint& k) const override {
    k.put("taylor_hood.u_n", s_.flow->state());
    k.put("taylor_hood.u_nm1", s_.flow->previous());
    Eigen::VectorXd at;
    double mass = 0;
    if (s_.flow->factors_state(at, mass)) {  // the chord method's factors, recomputed on resume
      k.put("taylor_hood.factors_at", at);
      k.put("taylor_hood.factors_mass", mass);
    }
  }
  void restore(const Checkpoint& k) override {
    const long n = s_.system->dofs();
    restored_ = Restored{k.step, k.vector("taylor_hood.u_n", n), k.vector("taylor_hood.u_nm1", n), {}, 0};
    if (k.has("taylor_hood.factors_at")) {
      restored_->factors_at = k.vector("taylor_hood.factors_at", n);
      restored_->factors_mass = k.scalar("taylor_hood.factors_mass");
    }
  }

 private:
  const Case& c_;
  const TimeParams& time_;
  TaylorHoodSetup s_;
  FluidSolution view_;
  struct Restored {
    int step;
    Eigen::VectorXd u_n, u_nm1;
    Eigen::VectorXd factors_at;  // empty: no reusable factors
    double factors_mass = 0;
  };
  std::optional<Restored> restored_;
};

}  // namespace

std::unique_ptr<FluidMarch> make_fluid_march(const Case& c, Mesh mesh) {
  if (c.fluid->taylor_hood()) return std::make_unique<TaylorHoodMarch>(c, std::move(mesh));
  return std::make_unique<MiniMarch>(c, std::move(mesh));
}

}  // namespace fsi
