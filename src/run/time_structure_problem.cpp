// [time] without [fluid] (SPEC §12): the structure alone in time, Newmark's average
// acceleration (solid/newmark.hpp) with contact at each new time, one contact problem
// per step (ContactGap::solve: one QP, re-linearised QPs for contact.gap = "normal", or
// Newton's QPs for a nonlinear material) warm-started from the last step's active set
// and displacement. From rest at u = 0 with the uniform velocity structure.v0 (a free
// body with structure.clamped = false), or from a checkpoint (--resume). Written as it
// goes (run/time_run.hpp): the frames structure-NNNNNN.vtu every time.output_every
// steps and the last, listed with their times in structure.pvd, and checkpoint.bin
// every time.checkpoint_every steps and at the end (also when stopped). Then
// history.csv (one line per step, and the initial state), the last state's
// structure.vtu and structure.png, and summary.json with the final state, the steps,
// the energy's balance and the contact intervals.
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "fem/probes.hpp"
#include "io/vtu.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/animation.hpp"
#include "run/outputs/frame_series.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/outputs/structure_history.hpp"
#include "run/outputs/structure_outputs.hpp"
#include "run/problem_kinds.hpp"
#include "run/run_case.hpp"
#include "run/steady_start.hpp"
#include "run/structure_setup.hpp"
#include "run/time_checkpoint.hpp"
#include "run/time_progress.hpp"
#include "run/time_run.hpp"
#include "solid/newmark.hpp"

namespace fsi {
namespace {

class TimeStructureProblem final : public Problem {
 public:
  TimeStructureProblem(const Case& c, const RunOptions& options)
      : c_(c), time_(*c.time), progress_(options.progress), run_(c, kind()) {}
  const char* kind() const override { return "contact"; }
  bool streams() const override { return true; }
  void open(RunOutputs& out) override { run_.open(out); }
  void resume(Checkpoint k) override { run_.resume(std::move(k)); }
  std::optional<int> resumed_frames_to() const override { return run_.resumed_frames_to(); }

  void set_up(PhaseTimes& times) override {
    Mesh mesh = in_phase(times, "mesh", [&] { return make_structure_mesh(c_); });
    stats_ = statistics(mesh);
    ScopedPhase phase(times, "structure");
    // The QP's own lines would come at every step: the time's progress line speaks instead.
    s_ = make_structure(c_, std::move(mesh), nullptr);
    probes_ = std::make_unique<ProbeSet>(s_.mesh(), c_.output.probes, s_.p2());
    if (const Checkpoint* k = run_.resumed()) restore(*k);  // checked before anything is written
  }

  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "structure");
    newmark_ = std::make_unique<Newmark>(s_.mass, time_.dt, s_.solver->free_dofs());
    if (!run_.resumed()) start();
    const int steps = time_.steps();
    progress_.start_after(state_.step);
    for (int k = run_.first_step(); k <= steps; ++k) {
      if ((interrupted_ = interrupt_requested())) break;
      try {
        step();
      } catch (const SolverFailure& e) {
        failure_ = "step " + std::to_string(k) + " (t = " + shortest(state_.t + time_.dt) + " s): " + e.what();
        break;
      }
      rows_.push_back(row(last_iterations_));
      if (run_.frame_due(k)) add_frame();
      if (run_.checkpoint_due(k)) save();
      fault_step(k);
      progress_.report(k, steps, state_.t);
    }
    save();  // the run's end, also when stopped or failed: --resume continues from it
    // What was computed, as a frame too (the checkpoint lists the regular frames only: a
    // resumed run writes the series an uninterrupted run would have).
    if ((interrupted_ || !failure_.empty()) && frames_.last_step() != state_.step) add_frame();
  }

  void measure(RunResult& r) override {
    RunMeasures& m = r.measures;
    m.structure_mesh = stats_;
    m.iterations = state_.step;
    m.converged = failure_.empty() && !interrupted_;
    m.status = !failure_.empty() ? "failed" : interrupted_ ? "interrupted" : "converged";
    m.failure = failure_;
    m.displacement = RunMeasures::Displacement{max_displacement(state_.u), component(state_.u, 1).minCoeff()};
    m.contact = summarize_contact(*s_.solver, state_.contact);
    r.displacement = state_.u;
    if (!failure_.empty()) r.exit_status = 1, r.failure = failure_;
    else if (interrupted_) r.exit_status = interrupted_exit_status();
  }

  void summarise(RunResult& r) override {
    Json& j = r.summary;
    j = summary_header(c_, kind());
    j["mesh"] = {{"structure", to_json(stats_)}};
    add_measures(j, r.measures);
    j["steps"] = state_.step;
    j["time"] = {{"dt", time_.dt}, {"t_end", time_.t_end}, {"scheme", "newmark"}, {"mass", c_.structure.mass},
                 {"steps", state_.step}, {"t", state_.t}, {"frames", frames_.size()}};
    j["solver"] = s_.qp->name();
    add_displacement_at(j, c_, s_.mesh(), state_.u, s_.p2());
    j["contact"] = to_json(*r.measures.contact);
    add_gap_summary(j["contact"], c_, s_, state_.contact);
    j["velocity"] = point_json(rows_.empty() ? initial_.velocity : rows_.back().velocity);
    j["energy"] = energy_json(initial_, rows_);
    j["contact_intervals"] = contact_intervals_json(initial_, rows_, time_.dt);
    if (run_.resumed()) j["resumed"] = run_.resumed_json(c_.output.dir);
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s: the structure alone in time (Newmark, %s mass, dt = %s s): %d steps to t = %s s on %d "
                  "triangles, %zu contact interval(s), energy drift %.2g of its largest value.",
                  c_.name.c_str(), c_.structure.mass.c_str(), shortest(time_.dt).c_str(), state_.step,
                  shortest(state_.t).c_str(), stats_.triangles, j["contact_intervals"].size(),
                  j["energy"]["max_relative_drift"].get<double>());
    r.report = std::string(text) + (failure_.empty() ? "" : " Failed at " + failure_ + ".") +
               (interrupted_ ? " Interrupted." : "") + " Results in " + c_.output.dir + "/.";
  }

  void final_fields(FinalFields& out) const override {
    out.structure = structure_arrays_if_solved(s_, state_.contact);
  }

  void write(RunOutputs& out) override {
    out.write("history.csv", [&](const std::string& p) { write_structure_history(p, initial_, rows_); });
    if (c_.output.vtu) {
      frames_.write_collection(out);
      out.write("structure.vtu", [&](const std::string& p) { write_structure_vtu(p, c_, s_, state_.contact, false); });
    }
    if (c_.output.png) {
      out.write("structure.png", [&](const std::string& p) { write_structure_png(p, c_, s_, state_.contact); });
      write_animation(out, pictures_);
    }
    write_case_toml(out, c_);
  }

 private:
  // At rest at u = 0 (or the steady state: time.start_from) with the velocity
  // structure.v0: step 0, its row and frame.
  void start() {
    const long dofs = 2L * s_.mesh().num_vertices();
    const Eigen::VectorXd v0 = initial_velocity(c_, s_.mesh());
    b_last_ = s_.b_applied;
    if (time_.start_from == "steady") {
      ContactSolution steady = steady_structure(c_);
      const Eigen::VectorXd u0 = steady.u;  // in equilibrium: no acceleration
      state_ = newmark_->start(0.0, u0, v0, Eigen::VectorXd::Zero(dofs), std::move(steady));
    } else {
      state_ = newmark_->start(0.0, Eigen::VectorXd::Zero(dofs), v0, b_last_, s_.solver->at_rest());
    }
    initial_ = row(0);
    add_frame();
  }

  // The frame's fields and its picture (the animation's).
  void add_frame() {
    if (!run_.out()) return;
    if (c_.output.vtu)
      frames_.add(*run_.out(), state_.step, state_.t,
                  [&](const std::string& p) { write_structure_vtu(p, c_, s_, state_.contact, false); });
    if (c_.output.png)
      pictures_.add(*run_.out(), state_.step, state_.t, [&](const std::string& p) {
        write_structure_png(p, c_, s_, state_.contact, c_.name + ": t = " + shortest(state_.t) + " s");
      });
  }

  // Everything the next step reads, and what the outputs have gathered so far.
  void save() const {
    run_.write_checkpoint(state_.step, state_.t, [&](Checkpoint& k) {
      put_newmark(k, state_);
      k.put("b_last", b_last_), k.put("work", work_);
      put_rows(k, initial_, rows_);
      frames_.save(k), pictures_.save(k);
    });
  }
  void restore(const Checkpoint& k) {
    const long dofs = 2L * s_.mesh().num_vertices();
    state_ = get_newmark(k, dofs);
    b_last_ = k.vector("b_last", dofs), work_ = k.scalar("work");
    get_rows(k, initial_, rows_);
    frames_.restore(k), pictures_.restore(k);
  }

  // One Newmark step: the contact problem for b_eff from the last state.
  void step() {
    const double t = (state_.step + 1) * time_.dt;
    const Eigen::VectorXd b = structure_load_varies(c_) ? structure_load(c_, s_.mesh(), s_.p2(), t) : s_.b_applied;
    ContactSolution next;
    try {
      next = s_.gap->solve(*s_.solver, newmark_->effective_load(state_, b), state_.u, &state_.contact);
    } catch (const QpError& e) {
      throw SolverFailure(std::string("the step's contact QP failed: ") + e.what());
    }
    if (!next.u.allFinite() || !next.qp.alpha.allFinite())
      throw SolverFailure("the step's contact problem returned a non-finite displacement or multiplier");
    // The last QP's iterations, and one more for each linearisation before it (ContactGap
    // counts the last solve's: it was a difference of two solves' counts).
    last_iterations_ = next.qp.iterations + next.newton.steps + (s_.gap->linearisations() - 1);
    // The applied load's work over the step, trapezoidal: exact for a load linear in t.
    work_ += 0.5 * (b_last_ + b).dot(next.u - state_.u);
    b_last_ = b;
    state_ = newmark_->advance(state_, std::move(next));
  }

  StructureRow row(int iterations) const {
    return structure_row(state_, *newmark_, s_, probes_.get(), work_, iterations);
  }

  const Case& c_;
  TimeParams time_;
  TimeProgress progress_;
  MeshStatistics stats_;
  StructureSetup s_;
  std::unique_ptr<ProbeSet> probes_;
  std::unique_ptr<Newmark> newmark_;
  NewmarkState state_;
  Eigen::VectorXd b_last_;
  double work_ = 0;
  int last_iterations_ = 0;
  StructureRow initial_;
  std::vector<StructureRow> rows_;
  FrameSeries frames_{"structure"}, pictures_{"frame", ".png"};
  std::string failure_;
  bool interrupted_ = false;
  TimeRun run_;
};

}  // namespace

std::unique_ptr<Problem> time_structure_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<TimeStructureProblem>(c, options);
}

}  // namespace fsi
