// [time] with structure.shape = "none" (SPEC §12): the fluid alone marched in time on
// its fixed mesh from rest, BDF1 or BDF2 (FluidTimeStepper), Stokes or Navier–Stokes,
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
#include "fluid/fluid_time_stepper.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "run/outputs/field_arrays.hpp"
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

double max_speed(const FluidSolution& s) {
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
    f_ = in_phase(times, "fluid", [&] { return make_fluid(c_, std::move(mesh), c_.coupling.eps); });
    if (const Checkpoint* k = run_.resumed()) restore(*k);  // checked before anything is written
  }

  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "fluid");
    const Mesh& mesh = *f_.mesh;
    PenalisedStokes& fluid = *f_.stokes;
    fluid.set_chi(Eigen::VectorXd::Zero(mesh.num_triangles()));  // no structure
    const auto data = [&](double t) {
      fluid.set_body_force(fluid_body_force(*c_.fluid, t));
      fluid.set_boundary_data(box_boundary_conditions(mesh, *c_.fluid, t));
    };
    // The steady flow for the data at t = 0 first (time.start_from = "steady"), before
    // the stepper adds the time derivative to the operator.
    const FluidSolution initial = time_.start_from == "steady" && !restored_ ? steady_flow(data) : fluid_at_rest(mesh);
    stepper_ = std::make_unique<FluidTimeStepper>(fluid, c_.fluid->rho, time_scheme(time_), time_.dt, initial);
    if (restored_) {
      stepper_->restore(restored_->step, restored_->v_n, restored_->v_nm1);
      if (restored_->step > 0) fluid.start_from(restored_->v_n);  // Newton's next start
      restored_.reset();
    } else {
      add_frame();
    }
    const int steps = time_.steps();
    progress_.start_after(stepper_->steps());
    for (int k = run_.first_step(); k <= steps; ++k) {
      if (interrupt_requested()) {
        interrupted_ = true;
        break;
      }
      try {
        stepper_->step(data);
      } catch (const SolverFailure& e) {
        // Newton's own words speak of a steady flow; in a step, a shorter one is the remedy.
        failure_ = "step " + std::to_string(k) + " (t = " + shortest(stepper_->time() + time_.dt) + " s): " + e.what() +
                   (f_.stokes->newton() ? "; in a time step, a smaller time.dt helps Newton's method" : "");
        break;
      }
      rows_.push_back(row());
      if (run_.frame_due(k)) add_frame();
      if (run_.checkpoint_due(k)) save();
      fault_step(k);
      progress_.report(k, steps, stepper_->time());
    }
    save();  // the run's end, also when stopped or failed: --resume continues from it
    // What was computed, as a frame too (the checkpoint lists the regular frames only: a
    // resumed run writes the series an uninterrupted run would have).
    if ((interrupted_ || !failure_.empty()) && frames_.last_step() != stepper_->steps()) add_frame();
  }

  void measure(RunResult& r) override {
    RunMeasures& m = r.measures;
    m.fluid_mesh = stats_;
    m.iterations = stepper_ ? stepper_->steps() : 0;
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
    j["steps"] = stepper_ ? stepper_->steps() : 0;  // SPEC §12's key; time.steps the same
    j["time"] = {{"dt", time_.dt}, {"t_end", time_.t_end}, {"scheme", time_.scheme},
                 {"steps", stepper_ ? stepper_->steps() : 0}, {"t", stepper_ ? stepper_->time() : 0.0},
                 {"frames", frames_.size()}};
    if (run_.resumed()) j["resumed"] = run_.resumed_json(c_.output.dir);
    j["obstacles"] = obstacles_json();
    const FluidSolution* last = rows_.empty() ? nullptr : &stepper_->state();
    if (!c_.output.fluid_probes.empty()) j["fluid_at"] = fluid_probes_json(c_, *f_.mesh, last);
    j["fluid"] = fluid_json(*f_.stokes);
    j["fluid"].update(flow_json(c_));
    char text[256];
    std::snprintf(text, sizeof text, "%s: the fluid alone in time (%s, dt = %s s): %d steps to t = %s s on %d triangles.",
                  c_.name.c_str(), time_.scheme.c_str(), shortest(time_.dt).c_str(), stepper_ ? stepper_->steps() : 0,
                  shortest(stepper_ ? stepper_->time() : 0.0).c_str(), stats_.triangles);
    r.report = std::string(text) + (failure_.empty() ? "" : " Failed at " + failure_ + ".") +
               (interrupted_ ? " Interrupted." : "") + " Results in " + c_.output.dir + "/.";
  }

  void final_fields(FinalFields& out) const override {
    if (stepper_) out.fluid = fluid_arrays(*f_.mesh, stepper_->state(), chi());
  }

  void write(RunOutputs& out) override {
    out.write("history.csv", [&](const std::string& p) { write_history(p); });
    if (c_.output.vtu && stepper_) {
      frames_.write_collection(out);
      out.write("fluid.vtu", [&](const std::string& p) { write_fluid_vtu(p, c_, *f_.mesh, stepper_->state(), chi()); });
    }
    if (c_.output.png && !rows_.empty()) {
      out.write("fluid.png", [&](const std::string& p) { picture(p); });
      write_animation(out, pictures_);
    }
    write_case_toml(out, c_);
  }

 private:
  Eigen::VectorXd chi() const { return Eigen::VectorXd::Zero(f_.mesh->num_triangles()); }
  FluidSolution steady_flow(const std::function<void(double)>& data) {
    data(0.0);
    try {
      FluidSolution v = f_.stokes->solve();
      v.exact_on = nullptr;
      return v;
    } catch (const SolverFailure& e) {
      throw SolverFailure(std::string("the steady flow at t = 0 (time.start_from = \"steady\"): ") + e.what());
    }
  }

  // The frame's fields and its picture (the animation's).
  void add_frame() {
    if (!run_.out()) return;
    if (c_.output.vtu)
      frames_.add(*run_.out(), stepper_->steps(), stepper_->time(),
                  [&](const std::string& p) { write_fluid_vtu(p, c_, *f_.mesh, stepper_->state(), chi()); });
    if (c_.output.png)
      pictures_.add(*run_.out(), stepper_->steps(), stepper_->time(), [&](const std::string& p) { picture(p); });
  }
  void picture(const std::string& path) const {
    write_fluid_png(path, c_, *f_.mesh, stepper_->state(), Mesh{}, {},
                    c_.name + ": fluid velocity magnitude at t = " + shortest(stepper_->time()) + " s",
                    "hF = " + shortest(c_.fluid->h) + ";  " + time_.scheme + ", dt = " + shortest(time_.dt));
  }

  // The stepper's v^n and v^{n−1}, the rows (each a step's t, Newton's steps, the
  // largest speed and the obstacles' forces) and the frames.
  void save() const {
    if (!stepper_) return;
    run_.write_checkpoint(stepper_->steps(), stepper_->time(), [&](Checkpoint& k) {
      put_fluid(k, "v_n", stepper_->state());
      put_fluid(k, "v_nm1", stepper_->previous());
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
    const int nv = f_.mesh->num_vertices(), nt = f_.mesh->num_triangles();
    restored_ = Restored{k.step, get_fluid(k, "v_n", nv, nt), get_fluid(k, "v_nm1", nv, nt)};
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
  StepRow row() const {
    StepRow r{stepper_->time(), 0, max_speed(stepper_->state()), {}};
    if (const FluidNewtonReport* n = f_.stokes->newton()) r.newton_steps = n->steps + n->picard_steps;
    MomentumModel model = momentum_model(*c_.fluid);
    model.inertia = stepper_->last_step_inertia();
    const VectorField f = fluid_body_force(*c_.fluid, r.t);
    for (const std::string& hole : obstacle_hole_names(c_))
      r.forces.push_back(hole_force(*f_.mesh, model, f, stepper_->state(), f_.mesh->label(hole), {}));
    return r;
  }

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
  FluidSetup f_;
  std::unique_ptr<FluidTimeStepper> stepper_;
  std::vector<StepRow> rows_;
  FrameSeries frames_{"fluid"}, pictures_{"frame", ".png"};
  std::string failure_;
  bool interrupted_ = false;
  TimeProgress progress_;
  TimeRun run_;
  struct Restored {
    int step;
    FluidSolution v_n, v_nm1;
  };
  std::optional<Restored> restored_;  // a checkpoint's state, until solve() gives it to the stepper
};

}  // namespace

std::unique_ptr<Problem> time_fluid_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<TimeFluidProblem>(c, options);
}

}  // namespace fsi
