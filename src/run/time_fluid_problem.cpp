// [time] with structure.shape = "none" (SPEC §12): the fluid alone marched in time on
// its fixed mesh from rest, BDF1 or BDF2 (FluidMarch: the mini element's
// FluidTimeStepper or Taylor–Hood's TaylorHoodFlow), Stokes or Navier–Stokes,
// the inflow fluid.Vmax and the body force fluid.f evaluated at each new time. Each
// step's forces on the obstacles by the residual method with the step's ρ∂v/∂t
// (MomentumModel::inertia). Outputs: history.csv (one line per step), the frames
// fluid-NNNNNN.vtu every time.output_every steps and the last, listed with their
// times in fluid.pvd, the last state's fluid.vtu and fluid.png, and summary.json with
// the final state, the steps and each obstacle's extreme forces with their times.
// The frames and checkpoint.bin are written as the run goes (run/time_run.hpp), as
// the structure's time run does; --resume continues from the checkpoint.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/fluid_march.hpp"
#include "run/fluid_setup.hpp"
#include "run/mesh_checks.hpp"
#include "run/outputs/animation.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "run/outputs/frame_series.hpp"
#include "run/outputs/obstacle_forces.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/problem_kinds.hpp"
#include "run/run_case.hpp"
#include "run/time_checkpoint.hpp"
#include "run/time_progress.hpp"
#include "run/time_run.hpp"

namespace fsi {
namespace {

struct StepRow {
  double t = 0;
  int newton_steps = 0;
  double max_speed = 0;
  std::vector<Point> forces;  // per obstacle
};

double max_speed(const FluidSolution& s) {  // at the vertices
  return std::sqrt((s.v1.array().square() + s.v2.array().square()).maxCoeff());
}

class TimeFluidProblem final : public Problem {
 public:
  TimeFluidProblem(const Case& c, const RunOptions& options)
      : c_(c), time_(*c.time), progress_(options.progress), run_(c, kind()) {}
  const char* kind() const override { return "fluid"; }
  bool streams() const override { return true; }
  void open(RunOutputs& out) override { run_.open(out); }
  void resume(Checkpoint k) override { run_.resume(std::move(k)); }
  std::optional<int> resumed_frames_to() const override { return run_.resumed_frames_to(); }

  // The fluid's own set-up, never the cache's: the time derivative is added to it.
  void set_up(PhaseTimes& times) override {
    Mesh mesh = in_phase(times, "mesh", [&] { return make_fluid_mesh(c_); });
    stats_ = statistics(mesh);
    march_ = in_phase(times, "fluid", [&] { return make_fluid_march(c_, std::move(mesh)); });
    if (const Checkpoint* k = run_.resumed()) restore(*k);  // checked before anything is written
  }

  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "fluid");
    const bool resumed = run_.resumed() != nullptr;
    march_->start(time_.start_from == "steady");
    started_ = true;
    if (!resumed) add_frame();
    const int steps = time_.steps();
    progress_.start_after(march_->steps());
    for (int k = run_.first_step(); k <= steps; ++k) {
      if (interrupt_requested()) {
        interrupted_ = true;
        break;
      }
      try {
        march_->step();
      } catch (const SolverFailure& e) {
        // Newton's own words speak of a steady flow; in a step, a shorter one is the remedy.
        failure_ = "step " + std::to_string(k) + " (t = " + shortest(march_->time() + time_.dt) + " s): " + e.what() +
                   (march_->navier_stokes() ? "; in a time step, a smaller time.dt helps Newton's method" : "");
        break;
      }
      rows_.push_back(row());
      if (run_.frame_due(k)) add_frame();
      if (run_.checkpoint_due(k)) save();
      fault_step(k);
      progress_.report(k, steps, march_->time());
    }
    save();  // the run's end, also when stopped or failed: --resume continues from it
    // What was computed, as a frame too (the checkpoint lists the regular frames only: a
    // resumed run writes the series an uninterrupted run would have).
    if ((interrupted_ || !failure_.empty()) && frames_.last_step() != march_->steps()) add_frame();
  }

  void measure(RunResult& r) override {
    RunMeasures& m = r.measures;
    m.fluid_mesh = stats_;
    m.iterations = started_ ? march_->steps() : 0;
    m.converged = failure_.empty() && !interrupted_;
    m.status = !failure_.empty() ? "failed" : interrupted_ ? "interrupted" : "converged";
    m.failure = failure_;
    if (!failure_.empty()) r.exit_status = 1, r.failure = failure_;
    else if (interrupted_) r.exit_status = interrupted_exit_status();
  }

  void summarise(RunResult& r) override {
    Json& j = r.summary;
    j = summary_header(c_, kind());
    j["mesh"] = {{"fluid", to_json(stats_)}};
    add_measures(j, r.measures);
    j["steps"] = started_ ? march_->steps() : 0;  // SPEC §12's key; time.steps the same
    j["time"] = {{"dt", time_.dt}, {"t_end", time_.t_end}, {"scheme", time_.scheme},
                 {"steps", started_ ? march_->steps() : 0}, {"t", started_ ? march_->time() : 0.0},
                 {"frames", frames_.size()}};
    if (run_.resumed()) j["resumed"] = run_.resumed_json(c_.output.dir);
    j["obstacles"] = obstacles_json();
    if (!c_.output.fluid_probes.empty())
      j["fluid_at"] = rows_.empty() ? fluid_probes_json(c_, march_->mesh(), nullptr) : march_->probes();
    j["fluid"] = march_ ? march_->json() : Json::object();
    j["fluid"].update(flow_json(c_));
    char text[256];
    std::snprintf(text, sizeof text, "%s: the fluid alone in time (%s, dt = %s s): %d steps to t = %s s on %d triangles.",
                  c_.name.c_str(), time_.scheme.c_str(), shortest(time_.dt).c_str(), started_ ? march_->steps() : 0,
                  shortest(started_ ? march_->time() : 0.0).c_str(), stats_.triangles);
    r.report = std::string(text) + (failure_.empty() ? "" : " Failed at " + failure_ + ".") +
               (interrupted_ ? " Interrupted." : "") + " Results in " + c_.output.dir + "/.";
  }

  void final_fields(FinalFields& out) const override {
    if (started_) out.fluid = fluid_arrays(march_->mesh(), march_->state(), chi());
  }

  void write(RunOutputs& out) override {
    out.write("history.csv", [&](const std::string& p) { write_history(p); });
    if (c_.output.vtu && started_) {
      frames_.write_collection(out);
      out.write("fluid.vtu", [&](const std::string& p) { write_fluid_vtu(p, c_, march_->mesh(), march_->state(), chi()); });
    }
    if (c_.output.png && !rows_.empty()) {
      out.write("fluid.png", [&](const std::string& p) { picture(p); });
      write_animation(out, pictures_);
    }
    write_case_toml(out, c_);
  }

 private:
  Eigen::VectorXd chi() const { return Eigen::VectorXd::Zero(march_->mesh().num_triangles()); }
  // The frame's fields and its picture (the animation's).
  void add_frame() {
    if (!run_.out()) return;
    if (c_.output.vtu)
      frames_.add(*run_.out(), march_->steps(), march_->time(),
                  [&](const std::string& p) { write_fluid_vtu(p, c_, march_->mesh(), march_->state(), chi()); });
    if (c_.output.png)
      pictures_.add(*run_.out(), march_->steps(), march_->time(), [&](const std::string& p) { picture(p); });
  }
  void picture(const std::string& path) const {
    write_fluid_png(path, c_, march_->mesh(), march_->state(), Mesh{}, {},
                    c_.name + ": fluid velocity magnitude at t = " + shortest(march_->time()) + " s",
                    "hF = " + shortest(c_.fluid->h) + ";  " + time_.scheme + ", dt = " + shortest(time_.dt));
  }

  // The stepper's v^n and v^{n−1}, the rows (each a step's t, Newton's steps, the
  // largest speed and the obstacles' forces) and the frames.
  void save() const {
    if (!started_) return;
    run_.write_checkpoint(march_->steps(), march_->time(), [&](Checkpoint& k) {
      march_->save(k);
      const long width = 3 + 2 * static_cast<long>(obstacle_hole_names(c_).size());
      Eigen::MatrixXd rows(width, static_cast<long>(rows_.size()));
      for (std::size_t i = 0; i < rows_.size(); ++i) {
        rows(0, long(i)) = rows_[i].t, rows(1, long(i)) = rows_[i].newton_steps, rows(2, long(i)) = rows_[i].max_speed;
        for (std::size_t o = 0; o < rows_[i].forces.size(); ++o) rows.block(3 + 2 * long(o), long(i), 2, 1) = rows_[i].forces[o];
      }
      k.put_matrix("rows", rows);
      frames_.save(k), pictures_.save(k);
    });
  }
  void restore(const Checkpoint& k) {
    march_->restore(k);
    const Eigen::MatrixXd rows = k.matrix("rows");
    const long obstacles = static_cast<long>(obstacle_hole_names(c_).size());
    if (rows.rows() != 3 + 2 * obstacles || rows.cols() != k.step)
      throw InputError(k.source + ": its rows do not fit this case (a damaged checkpoint)");
    rows_.clear();
    for (long i = 0; i < rows.cols(); ++i) {
      StepRow r{rows(0, i), int(rows(1, i)), rows(2, i), {}};
      for (long o = 0; o < obstacles; ++o) r.forces.emplace_back(rows(3 + 2 * o, i), rows(4 + 2 * o, i));
      rows_.push_back(r);
    }
    frames_.restore(k), pictures_.restore(k);
  }

  // This step's row: the forces with the step's ρ∂v/∂t and f_F at its time.
  StepRow row() const { return {march_->time(), march_->newton_steps(), max_speed(march_->state()), march_->forces()}; }

  // obstacles[i]: the last step's force, and each component's largest and smallest
  // value over the run with their times (the DFG 2D-3 benchmark's C_D,max, C_L,max).
  Json obstacles_json() const {
    Json list = Json::array();
    const std::size_t count = obstacle_hole_names(c_).size();
    for (std::size_t i = 0; i < count; ++i) {
      if (rows_.empty()) {
        list.push_back({{"force", nullptr}});
        continue;
      }
      std::array<std::size_t, 2> hi{0, 0}, lo{0, 0};
      for (std::size_t k = 0; k < rows_.size(); ++k)
        for (int c = 0; c < 2; ++c) {
          if (rows_[k].forces[i][c] > rows_[hi[c]].forces[i][c]) hi[c] = k;
          if (rows_[k].forces[i][c] < rows_[lo[c]].forces[i][c]) lo[c] = k;
        }
      const auto value = [&](const std::array<std::size_t, 2>& at) {
        return Json::array({rows_[at[0]].forces[i][0], rows_[at[1]].forces[i][1]});
      };
      const auto time = [&](const std::array<std::size_t, 2>& at) { return Json::array({rows_[at[0]].t, rows_[at[1]].t}); };
      list.push_back({{"force", point_json(rows_.back().forces[i])},
                      {"force_max", value(hi)},
                      {"force_max_time", time(hi)},
                      {"force_min", value(lo)},
                      {"force_min_time", time(lo)}});
    }
    return list;
  }

  void write_history(const std::string& path) const {
    write_atomically(path, [&](std::ostream& out) {
      out << "step,t,newton_steps,max_speed";
      for (std::size_t i = 1; i <= obstacle_hole_names(c_).size(); ++i)
        out << ",obstacle_" << i << "_force_x,obstacle_" << i << "_force_y";
      out << "\n";
      for (std::size_t k = 0; k < rows_.size(); ++k) {  // every number to its last digit
        out << k + 1 << "," << shortest(rows_[k].t) << "," << rows_[k].newton_steps << "," << shortest(rows_[k].max_speed);
        for (const Point& F : rows_[k].forces) out << "," << shortest(F.x()) << "," << shortest(F.y());
        out << "\n";
      }
    });
  }

  const Case& c_;
  TimeParams time_;
  MeshStatistics stats_;
  std::unique_ptr<FluidMarch> march_;
  bool started_ = false;  // march_ has a state (start() returned)
  std::vector<StepRow> rows_;
  FrameSeries frames_{"fluid"}, pictures_{"frame", ".png"};
  std::string failure_;
  bool interrupted_ = false;
  TimeProgress progress_;
  TimeRun run_;
};

}  // namespace

std::unique_ptr<Problem> time_fluid_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<TimeFluidProblem>(c, options);
}

}  // namespace fsi
