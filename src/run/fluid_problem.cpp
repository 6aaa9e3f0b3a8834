// structure.shape = "none" (SPEC §9): the fluid alone in its box with its holes, no
// structure at all (χ = 0 everywhere, so the penalty term vanishes): one Stokes solve,
// and the fluid's force on each obstacle (SPEC §10, the residual method). The mini
// element's system comes from the run's set-up cache (a sweep reuses it); the
// Taylor–Hood element's (fluid.element) is built here.
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/timer.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "run/fluid_setup.hpp"
#include "run/outputs/obstacle_forces.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/problem_kinds.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/taylor_hood_setup.hpp"

namespace fsi {
namespace {

// " Force on obstacle i: (Fx, Fy) N/m." for each obstacle with a force.
std::string force_sentences(const Json& forces) {
  std::string out;
  char text[128];
  for (std::size_t i = 0; i < forces.size(); ++i) {
    const Json& F = forces[i]["force"];
    if (!F.is_array()) continue;
    std::snprintf(text, sizeof text, " Force on obstacle %zu: (%.6g, %.6g) N/m.", i + 1, F[0].get<double>(), F[1].get<double>());
    out += text;
  }
  return out;
}

std::string fluid_report(const Case& c, const PenalisedStokes& stokes, const MeshStatistics& stats, const Json& forces) {
  const FluidTiming& t = stokes.timing();
  char text[512];
  std::snprintf(text, sizeof text, "%s: the fluid alone (no structure): %d unknowns on %d triangles, solved in %.3f s (%s).",
                c.name.c_str(), stokes.unknowns(), stats.triangles, t.assembly + t.factorization + t.solve,
                stokes.solver_name().c_str());
  return text + force_sentences(forces) + " Results in " + c.output.dir + "/.";
}

std::string taylor_hood_report(const Case& c, const TaylorHoodSetup& th, const MeshStatistics& stats, const Json& forces) {
  const TaylorHoodTiming& t = th.flow->timing();
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: the fluid alone (no structure), Taylor–Hood P2/P1 with %d curved triangles: %d unknowns on %d "
                "triangles, solved in %.3f s (%s).",
                c.name.c_str(), th.geometry->curved_triangles(), th.system->unknowns(), stats.triangles,
                t.assembly + t.factorization + t.solve, th.flow->solver_name().c_str());
  return text + force_sentences(forces) + " Results in " + c.output.dir + "/.";
}

class FluidProblem final : public Problem {
 public:
  FluidProblem(const Case& c, const RunOptions& options)
      : c_(c), cache_(options.cache ? *options.cache : local_cache_) {}
  const char* kind() const override { return "fluid"; }

  void set_up(PhaseTimes& times) override {
    if (c_.fluid->taylor_hood()) {
      Mesh mesh = in_phase(times, "mesh", [&] { return make_fluid_mesh(c_); });
      stats_ = statistics(mesh);
      th_ = in_phase(times, "fluid", [&] { return make_taylor_hood(c_, std::move(mesh)); });
      return;
    }
    stats_ = in_phase(times, "mesh", [&] { return statistics(cache_.fluid_mesh(c_)); });
    f_ = in_phase(times, "fluid", [&] { return &cache_.fluid(c_); });
  }

  // A failed solve is kept: summary.json then also holds what the fluid solver did
  // (Newton's residual history, SPEC §10).
  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "fluid");
    try {
      if (th_.flow) {
        th_.flow->solve();
        if (!th_.flow->state().allFinite()) throw SolverFailure("the fluid solve failed: a non-finite field");
        th_view_ = th_.flow->vertex_view();
        fluid_ = &th_view_;
        th_forces_ = taylor_hood_hole_forces(th_, c_);
      } else {
        fluid_ = &solve_fluid_once(*f_->stokes, Eigen::VectorXd::Zero(f_->mesh->num_triangles()));  // χ = 0: no structure
      }
    } catch (const SolverFailure& e) {
      failure_ = e.what();
    }
  }

  void measure(RunResult& r) override {
    RunMeasures& m = r.measures;
    m.fluid_mesh = stats_;
    m.converged = failure_.empty();
    m.status = failure_.empty() ? "converged" : "failed";
    m.failure = failure_;
    if (!failure_.empty()) r.exit_status = 1, r.failure = failure_;
  }

  void summarise(RunResult& r) override {
    Json& j = r.summary;
    j = summary_header(c_, kind());
    j["mesh"] = {{"fluid", to_json(stats_)}};
    add_measures(j, r.measures);
    j["obstacles"] = th_.flow ? hole_forces_json(c_, fluid_ ? &th_forces_ : nullptr) : obstacle_forces_json(c_, *f_);
    if (!c_.output.fluid_probes.empty())
      j["fluid_at"] = th_.flow ? (fluid_ ? taylor_hood_probes_json(c_, th_) : fluid_probes_json(c_, mesh(), nullptr))
                               : fluid_probes_json(c_, *f_);
    j["fluid"] = th_.flow ? taylor_hood_json(th_) : fluid_json(*f_->stokes);
    j["fluid"].update(flow_json(c_));
    if (!failure_.empty()) r.report = c_.name + ": failed: " + failure_;
    else if (th_.flow) r.report = taylor_hood_report(c_, th_, stats_, j["obstacles"]);
    else r.report = fluid_report(c_, *f_->stokes, stats_, j["obstacles"]);
  }

  void final_fields(FinalFields& out) const override {
    if (fluid_) out.fluid = fluid_arrays(mesh(), *fluid_, chi());
  }

  void write(RunOutputs& out) override {
    if (!fluid_) return write_case_toml(out, c_);
    if (c_.output.vtu)
      out.write("fluid.vtu", [&](const std::string& p) {
        write_fluid_vtu(p, c_, mesh(), *fluid_, chi());
      });
    if (c_.output.png)
      out.write("fluid.png", [&](const std::string& p) {
        write_fluid_png(p, c_, mesh(), *fluid_, Mesh{}, {}, c_.name + ": fluid velocity magnitude (no structure)",
                        "hF = " + shortest(c_.fluid->h) + ";  no structure");
      });
    if (const std::optional<WorldBox> wake = wake_box(c_); c_.output.png && wake)  // where the flow separates
      out.write("fluid-wake.png", [&](const std::string& p) {
        write_fluid_png(p, c_, mesh(), *fluid_, Mesh{}, {}, "", "the first obstacle's wake;  hF = " + shortest(c_.fluid->h),
                        &*wake);
      });
    write_case_toml(out, c_);
  }

 private:
  const Mesh& mesh() const { return th_.flow ? *th_.mesh : *f_->mesh; }
  Eigen::VectorXd chi() const {
    return th_.flow ? Eigen::VectorXd::Zero(th_.mesh->num_triangles()) : f_->stokes->last_solution_chi();
  }
  const Case& c_;
  SetupCache local_cache_;
  SetupCache& cache_;
  MeshStatistics stats_;
  FluidSetup* f_ = nullptr;
  const FluidSolution* fluid_ = nullptr;
  TaylorHoodSetup th_;            // fluid.element = "taylor-hood"
  FluidSolution th_view_;         // its state at the vertices (the outputs')
  std::vector<Point> th_forces_;  // on each hole
  std::string failure_;
};

}  // namespace

std::unique_ptr<Problem> fluid_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<FluidProblem>(c, options);
}

}  // namespace fsi
