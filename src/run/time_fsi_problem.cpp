// [time] with a structure and a penalised fluid (SPEC §12): the coupled problem
// marched in time. Each step t^n → t^{n+1}:
//   the fluid's data at t^{n+1} and its history (FluidTimeStepper::begin);
//   the structure's effective load b^{n+1} + M[(4/Δt²)(u^n + Δt u̇^n) + ü^n] (Newmark);
//   the fixed point of §5 over u^{n+1} (FixedPointCoupling, one window a step: the
//   relaxation's window ends, IQN-ILS keeping coupling.reuse steps' pairs), each pass
//   the fluid's step at the pass's χ and structure velocity (TimePenalisedStep) and
//   the contact problem with the operator A_S + (4/Δt²) M;
//   from the predictor u^n + Δt u̇^n; then the fluid's and the structure's states advance.
// What is reused from step to step: the fluid's pattern and symbolic factorisation
// (χ and the time derivative change its values: one numeric factorisation per pass),
// the structure's factorisation of A_S + (4/Δt²) M, the relaxation's secant pairs.
// Outputs: the penalised run's final files (fluid.vtu, structure.vtu, fsi.png,
// summary.json), history.csv one line per step, and, written as the run goes
// (run/time_run.hpp), the frames structure-NNNNNN.vtu (deformed) and fluid-NNNNNN.vtu
// every time.output_every steps, in structure.pvd and fluid.pvd, and checkpoint.bin
// (--resume): the states of both, the relaxation's kept secant pairs, the history.
#include <cmath>
#include <cstdio>
#include <optional>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "coupling/fixed_point.hpp"
#include "coupling/time_penalised_step.hpp"
#include "io/vtu.hpp"
#include "run/case_fields.hpp"
#include "run/outputs/animation.hpp"
#include "run/outputs/coupling_outputs.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "run/outputs/frame_series.hpp"
#include "run/outputs/structure_history.hpp"
#include "run/outputs/structure_outputs.hpp"
#include "run/penalised_problem.hpp"
#include "run/problem_kinds.hpp"
#include "run/steady_start.hpp"
#include "run/time_checkpoint.hpp"
#include "run/time_progress.hpp"
#include "run/time_run.hpp"

namespace fsi {
namespace {

class TimePenalisedFsi final : public PenalisedProblem {
 public:
  TimePenalisedFsi(const Case& c, const RunOptions& options)
      : PenalisedProblem(c, options), time_(*c.time), progress_(options.progress), run_(c, "fsi") {}
  bool streams() const override { return true; }
  void open(RunOutputs& out) override { run_.open(out); }
  void resume(Checkpoint k) override { run_.resume(std::move(k)); }
  std::optional<int> resumed_frames_to() const override { return run_.resumed_frames_to(); }

  void set_up(PhaseTimes& times) override {
    PenalisedProblem::set_up(times);
    if (const Checkpoint* k = run_.resumed()) restore(*k);  // checked before anything is written
  }

  void solve(PhaseTimes& times) override {
    // The steady state first (time.start_from), before the stepper adds ρ∂v/∂t.
    std::optional<SteadyCoupledStart> steady;
    if (time_.start_from == "steady" && !restored_) steady = steady_coupled(c_, *s_, *f_, fluid_force());
    Parts parts(*this, steady ? steady->fluid : fluid_at_rest(*f_->mesh));
    newmark_ = std::make_unique<Newmark>(s_->mass, time_.dt, s_->solver->free_dofs());
    if (restored_) continue_from(parts);
    else start(parts, steady ? &*steady : nullptr);
    const int steps = time_.steps();
    progress_.start_after(state_.step);
    bool attempted = false;  // a step was begun (its coupling ran, converged or not)
    for (int k = run_.first_step(); k <= steps; ++k) {
      if ((interrupted_ = interrupt_requested())) break;
      attempted = true;
      if (!step(parts, k, times)) break;
      if (run_.frame_due(k)) add_frame(parts);
      if (run_.checkpoint_due(k)) save(parts);
      fault_step(k);
      progress_.report(k, steps, state_.t);
    }
    save(parts);  // the run's end, also when stopped or failed: --resume continues from it
    // What was computed, as a frame too (the checkpoint lists the regular frames only: a
    // resumed run writes the series an uninterrupted run would have).
    if ((interrupted_ || !result_.failure.empty() || !result_.converged) && structure_frames_.last_step() != state_.step)
      add_frame(parts);
    // Resumed at its end (or stopped before its first step): nothing was to converge.
    // A first step whose coupling did not converge is not that: its status stands.
    if (!attempted && result_.failure.empty()) result_.converged = true;
    result_.structure = state_.contact;  // the final state the penalised run measures
    if (interrupted_) result_.interrupted = true;
    complete_fluid();
  }

  void summarise(RunResult& r) override {
    PenalisedProblem::summarise(r);
    Json& j = r.summary;
    j["steps"] = state_.step;
    j["time"] = {{"dt", time_.dt}, {"t_end", time_.t_end}, {"scheme", time_.scheme}, {"structure_scheme", "newmark"},
                 {"mass", c_.structure.mass}, {"steps", state_.step}, {"t", state_.t}, {"frames", structure_frames_.size()},
                 {"passes", passes_json()}};
    j["velocity"] = point_json(rows_.empty() ? initial_.velocity : rows_.back().velocity);
    j["energy"] = energy_json(initial_, rows_);
    j["contact_intervals"] = contact_intervals_json(initial_, rows_, time_.dt);
    if (run_.resumed()) j["resumed"] = run_.resumed_json(c_.output.dir);
  }

 private:
  // What the loop is made of, built once per run.
  struct Parts {
    Parts(TimePenalisedFsi& p, const FluidSolution& initial)
        : M(assemble_vector_mass(p.s_->mesh())),
          relaxation(make_relaxation(p.c_.coupling.scheme,
                                     {.omega0 = p.c_.coupling.omega, .reused_windows = p.c_.coupling.reuse}, M)),
          stepper(*p.f_->stokes, p.c_.fluid->rho, time_scheme(p.time_), p.time_.dt, initial),
          penalty(std::make_shared<PenaltyVelocityLoad>(p.f_->mesh->num_triangles(), p.f_->stokes->eps())),
          fluid({p.s_->mesh(), *p.f_->stokes, stepper, *penalty, *p.f_->locator, *p.f_->chi}),
          structure(*p.s_->solver, p.s_->gap.get()),
          loop(fluid, structure, b_eff, *relaxation, M, p.c_.coupling.tol, p.c_.coupling.max_iterations) {
      p.f_->stokes->add_term(penalty);
    }
    SparseMatrix M;  // L²(Ω_S0): the stop's and the relaxation's
    std::unique_ptr<Relaxation> relaxation;
    FluidTimeStepper stepper;
    std::shared_ptr<PenaltyVelocityLoad> penalty;
    TimePenalisedStep fluid;
    StructureStep structure;
    Eigen::VectorXd b_eff;  // the step's b^{n+1} + M[...], the loop's "applied" load
    FixedPointCoupling loop;
  };

  int dofs() const { return 2 * s_->mesh().num_vertices(); }

  // From rest, or the steady state (time.start_from), with structure.v0: step 0's
  // state, row and frame.
  void start(Parts& p, const SteadyCoupledStart* steady) {
    if (steady)  // in equilibrium: no acceleration
      state_ = newmark_->start(0.0, steady->structure.u, initial_velocity(c_, s_->mesh()), Eigen::VectorXd::Zero(dofs()), steady->structure);
    else
      state_ = newmark_->start(0.0, Eigen::VectorXd::Zero(dofs()), initial_velocity(c_, s_->mesh()), s_->b_applied, s_->solver->at_rest());
    b_last_ = s_->b_applied;
    fluid_last_ = steady ? steady->fluid_load : Eigen::VectorXd::Zero(dofs());
    initial_ = row(0, 0);
    add_frame(p);
  }

  // From a checkpoint: the loop's parts take back what they carry from step to step.
  void continue_from(Parts& p) {
    p.stepper.restore(state_.step, restored_->v_n, restored_->v_nm1);
    if (state_.step > 0) f_->stokes->start_from(restored_->v_n);  // Newton's next start
    f_->stokes->restore_near_region(std::move(restored_->near_region));
    p.relaxation->restore(restored_->relaxation);
    p.structure.begin();  // as the first window's run() does
    restored_.reset();
  }

  // The frame's fields and its picture (the animation's): |v| with the deformed structure.
  void add_frame(const Parts& p) {
    if (!run_.out()) return;
    if (c_.output.vtu) {
      structure_frames_.add(*run_.out(), state_.step, state_.t,
                            [&](const std::string& path) { write_structure_vtu(path, c_, *s_, state_.contact, true); });
      fluid_frames_.add(*run_.out(), state_.step, state_.t, [&](const std::string& path) {
        write_fluid_vtu(path, c_, *f_->mesh, p.stepper.state(), f_->stokes->chi());
      });
    }
    if (!c_.output.png) return;
    const Eigen::VectorXd& u = state_.u;
    const Mesh deformed = displaced(s_->mesh(), component(u, 0), component(u, 1));
    pictures_.add(*run_.out(), state_.step, state_.t, [&](const std::string& path) {
      write_fluid_png(path, c_, *f_->mesh, p.stepper.state(), deformed, active_vertices(*s_->solver, state_.contact),
                      c_.name + ": fluid velocity magnitude at t = " + shortest(state_.t) + " s",
                      "eps = " + shortest(c_.coupling.eps) + ", hF = " + shortest(c_.fluid->h) + ", hS = " +
                          shortest(c_.structure.h) + ";  " + time_.scheme + " and Newmark, dt = " + shortest(time_.dt));
    });
  }

  void save(const Parts& p) const {
    run_.write_checkpoint(state_.step, state_.t, [&](Checkpoint& k) {
      put_newmark(k, state_);
      k.put("b_last", b_last_), k.put("fluid_last", fluid_last_), k.put("work", work_);
      put_fluid(k, "v_n", p.stepper.state());
      put_fluid(k, "v_nm1", p.stepper.previous());
      put_near_region(k, f_->stokes->near_region_state());
      for (const auto& [name, values] : p.relaxation->saved()) k.put("relaxation." + name, values);
      put_rows(k, initial_, rows_);
      structure_frames_.save(k), fluid_frames_.save(k), pictures_.save(k);
    });
  }
  void restore(const Checkpoint& k) {
    const long n = dofs();
    const int nv = f_->mesh->num_vertices(), nt = f_->mesh->num_triangles();
    state_ = get_newmark(k, n);
    b_last_ = k.vector("b_last", n), fluid_last_ = k.vector("fluid_last", n), work_ = k.scalar("work");
    restored_ = Restored{get_fluid(k, "v_n", nv, nt), get_fluid(k, "v_nm1", nv, nt), {}, get_near_region(k, nt)};
    const std::string prefix = "relaxation.";
    for (const auto& [name, values] : k.arrays())
      if (name.rfind(prefix, 0) == 0) restored_->relaxation[name.substr(prefix.size())] = values;
    if (!restored_->relaxation.count("projections") ||
        (c_.coupling.scheme == "iqn-ils" && !restored_->relaxation.count("V")))
      throw InputError(k.source + ": its relaxation's state is not coupling.scheme = \"" + c_.coupling.scheme + "\"'s");
    get_rows(k, initial_, rows_);
    structure_frames_.restore(k), fluid_frames_.restore(k), pictures_.restore(k);
  }

  // One time step; false (the run ends, the state at t^n kept) if its coupling failed
  // or did not converge.
  bool step(Parts& p, int k, PhaseTimes& times) {
    const double t = k * time_.dt;
    const Eigen::VectorXd b = structure_load_varies(c_) ? structure_load(c_, s_->mesh(), s_->p2(), t) : s_->b_applied;
    p.b_eff = newmark_->effective_load(state_, b);
    const Mesh& mesh = *f_->mesh;
    p.stepper.begin([&](double tn) {
      f_->stokes->set_body_force(fluid_body_force(*c_.fluid, tn));
      f_->stokes->set_boundary_data(box_boundary_conditions(mesh, *c_.fluid, tn));
    });
    p.fluid.begin_step(state_.u, state_.v);
    const Eigen::VectorXd predictor = state_.u + time_.dt * state_.v;
    CouplingResult r;
    if (k == 1) {
      p.loop.initial = predictor;
      r = p.loop.run();
    } else {
      r = p.loop.next_window(predictor);
    }
    for (const auto& rec : r.history) {
      times.add("fluid", rec.t_fluid), times.add("structure", rec.t_structure);
      times.add("transfer", rec.t_transfer), times.add("chi", rec.t_chi);
    }
    const std::string when = "step " + std::to_string(k) + " (t = " + shortest(t) + " s): ";
    if (!r.failure.empty() || !r.converged) {
      result_ = r;
      result_.structure = state_.contact;
      if (!r.failure.empty()) result_.failure = when + r.failure;
      else if (r.interrupted) interrupted_ = true;
      return false;
    }
    p.stepper.accept();
    // The applied loads' and the fluid's work over the step, trapezoidal in time.
    const Eigen::VectorXd du = r.structure.u - state_.u;
    work_ += 0.5 * (b_last_ + b).dot(du) + 0.5 * (fluid_last_ + r.fluid_load).dot(du);
    b_last_ = b;
    fluid_last_ = r.fluid_load;
    const int passes = r.iterations;
    result_ = std::move(r);
    state_ = newmark_->advance(state_, result_.structure);
    rows_.push_back(row(passes, state_.contact.qp.iterations));
    return true;
  }

  StructureRow row(int passes, int qp_iterations) const {
    StructureRow r = structure_row(state_, *newmark_, *s_, nullptr, work_, qp_iterations);
    r.passes = passes;
    r.fluid_force = resultant(fluid_last_);
    return r;
  }

  Json passes_json() const {
    int total = 0, most = 0;
    for (const StructureRow& r : rows_) total += r.passes, most = std::max(most, r.passes);
    return {{"total", total}, {"mean", rows_.empty() ? 0.0 : double(total) / double(rows_.size())}, {"max", most}};
  }

  void write_structure(RunOutputs& out, bool fluid_vtu_written) override {
    write_coupled_files(out, c_, *s_, result_, fluid_ != nullptr, fluid_vtu_written, false, false);
    out.write("history.csv", [&](const std::string& p) { write_structure_history(p, initial_, rows_); });
    if (c_.output.png) write_animation(out, pictures_);
    if (!c_.output.vtu) return;
    structure_frames_.write_collection(out);
    fluid_frames_.write_collection(out);
  }
  const char* picture_name() const override { return "fsi.png"; }
  std::string picture_state() const override { return "t = " + shortest(state_.t) + " s, " + time_.scheme; }
  std::vector<int> contact_vertices() const override { return active_vertices(*s_->solver, state_.contact); }
  void measure_structure(RunMeasures& m) override { measure_coupled_structure(m); }
  void summarise_structure(Json& j, const RunMeasures& m) override { summarise_coupled_structure(j, m); }

  std::string report(const RunMeasures& m) const override {
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s: fluid and structure in time (%s and Newmark, dt = %s s): %d steps to t = %s s, %.3g coupling "
                  "passes a step on average; max displacement %.4g m at the end. Fluid %d triangles, structure %d.",
                  c_.name.c_str(), time_.scheme.c_str(), shortest(time_.dt).c_str(), state_.step,
                  shortest(state_.t).c_str(), passes_json()["mean"].get<double>(), m.displacement ? m.displacement->max : 0.0,
                  m.fluid_mesh.triangles, m.structure_mesh.triangles);
    std::string out = text;
    if (!result_.failure.empty()) out += " Failed at " + result_.failure + ".";
    else if (!result_.converged) out += " The coupling did not converge at step " + std::to_string(state_.step + 1) + ".";
    if (interrupted_) out += " Interrupted.";
    return out + " Results in " + c_.output.dir + "/.";
  }

  TimeParams time_;
  TimeProgress progress_;
  std::unique_ptr<Newmark> newmark_;
  NewmarkState state_;
  Eigen::VectorXd b_last_, fluid_last_;
  double work_ = 0;
  StructureRow initial_;
  std::vector<StructureRow> rows_;
  FrameSeries structure_frames_{"structure"}, fluid_frames_{"fluid"}, pictures_{"frame", ".png"};
  bool interrupted_ = false;
  TimeRun run_;
  struct Restored {
    FluidSolution v_n, v_nm1;
    Relaxation::State relaxation;
    NearRegionState near_region;
  };
  std::optional<Restored> restored_;  // a checkpoint's, until solve() gives it to the loop's parts
};

}  // namespace

std::unique_ptr<Problem> time_penalised_fsi(const Case& c, const RunOptions& options) {
  return std::make_unique<TimePenalisedFsi>(c, options);
}

}  // namespace fsi
