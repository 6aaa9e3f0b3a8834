// structure.shape = "none" (SPEC §9): the fluid alone in its box with its holes, no
// structure at all (χ = 0 everywhere, so the penalty term vanishes): one Stokes solve,
// and the fluid's force on each obstacle (SPEC §10, the residual method).
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

namespace fsi {
namespace {

std::string fluid_report(const Case& c, const PenalisedStokes& stokes, const MeshStatistics& stats, const Json& forces) {
  const FluidTiming& t = stokes.timing();
  char text[512];
  std::snprintf(text, sizeof text, "%s: the fluid alone (no structure): %d unknowns on %d triangles, solved in %.3f s (%s).",
                c.name.c_str(), stokes.unknowns(), stats.triangles, t.assembly + t.factorization + t.solve,
                stokes.solver_name().c_str());
  std::string report = text;
  for (std::size_t i = 0; i < forces.size(); ++i) {
    const Json& F = forces[i]["force"];
    if (!F.is_array()) continue;
    std::snprintf(text, sizeof text, " Force on obstacle %zu: (%.6g, %.6g) N/m.", i + 1, F[0].get<double>(), F[1].get<double>());
    report += text;
  }
  return report + " Results in " + c.output.dir + "/.";
}

class FluidProblem final : public Problem {
 public:
  FluidProblem(const Case& c, const RunOptions& options)
      : c_(c), cache_(options.cache ? *options.cache : local_cache_) {}
  const char* kind() const override { return "fluid"; }

  void set_up(PhaseTimes& times) override {
    stats_ = in_phase(times, "mesh", [&] { return statistics(cache_.fluid_mesh(c_)); });
    f_ = in_phase(times, "fluid", [&] { return &cache_.fluid(c_); });
  }

  // A failed solve is kept: summary.json then also holds what the fluid solver did
  // (Newton's residual history, SPEC §10).
  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "fluid");
    try {
      fluid_ = &solve_fluid_once(*f_->stokes, Eigen::VectorXd::Zero(f_->mesh->num_triangles()));  // χ = 0: no structure
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
    j["obstacles"] = obstacle_forces_json(c_, *f_);
    if (!c_.output.fluid_probes.empty()) j["fluid_at"] = fluid_probes_json(c_, *f_);
    j["fluid"] = fluid_json(*f_->stokes);
    j["fluid"].update(flow_json(c_));
    r.report = failure_.empty() ? fluid_report(c_, *f_->stokes, stats_, j["obstacles"])
                                : c_.name + ": failed: " + failure_;
  }

  void final_fields(FinalFields& out) const override {
    if (fluid_) out.fluid = fluid_arrays(*f_->mesh, *fluid_, f_->stokes->last_solution_chi());
  }

  void write(RunOutputs& out) override {
    if (!fluid_) return write_case_toml(out, c_);
    if (c_.output.vtu)
      out.write("fluid.vtu", [&](const std::string& p) {
        write_fluid_vtu(p, c_, *f_->mesh, *fluid_, f_->stokes->last_solution_chi());
      });
    if (c_.output.png)
      out.write("fluid.png", [&](const std::string& p) {
        write_fluid_png(p, c_, *f_->mesh, *fluid_, Mesh{}, {}, c_.name + ": fluid velocity magnitude (no structure)",
                        "hF = " + shortest(c_.fluid->h) + ";  no structure");
      });
    if (const std::optional<WorldBox> wake = wake_box(c_); c_.output.png && wake)  // where the flow separates
      out.write("fluid-wake.png", [&](const std::string& p) {
        write_fluid_png(p, c_, *f_->mesh, *fluid_, Mesh{}, {}, "", "the first obstacle's wake;  hF = " + shortest(c_.fluid->h),
                        &*wake);
      });
    write_case_toml(out, c_);
  }

 private:
  const Case& c_;
  SetupCache local_cache_;
  SetupCache& cache_;
  MeshStatistics stats_;
  FluidSetup* f_ = nullptr;
  const FluidSolution* fluid_ = nullptr;
  std::string failure_;
};

}  // namespace

std::unique_ptr<Problem> fluid_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<FluidProblem>(c, options);
}

}  // namespace fsi
