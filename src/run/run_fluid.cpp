// structure.shape = "none" (SPEC §9): the fluid alone in its box with its holes, no
// structure at all (χ = 0 everywhere, so the penalty term vanishes): one Stokes solve,
// and the fluid's force on each obstacle (SPEC §10, the residual method).
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/timer.hpp"
#include "io/atomic_file.hpp"
#include "run/fluid_outputs.hpp"
#include "run/fluid_setup.hpp"
#include "run/obstacle_forces.hpp"
#include "run/output_dir.hpp"
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

}  // namespace

RunResult run_fluid_case(const Case& c, const RunOptions& options) {
  PhaseTimes times;
  const Stopwatch total;
  SetupCache local_cache;
  SetupCache& cache = options.cache ? *options.cache : local_cache;
  const MeshStatistics stats = in_phase(times, "mesh", [&] { return statistics(cache.fluid_mesh(c)); });
  FluidSetup& f = *in_phase(times, "fluid", [&] { return &cache.fluid(c); });
  const FluidSolution* fluid = nullptr;
  {
    ScopedPhase phase(times, "fluid");
    fluid = &solve_fluid_once(*f.stokes, Eigen::VectorXd::Zero(f.mesh->num_triangles()));  // χ = 0: no structure
  }
  RunResult r;
  RunMeasures& m = r.measures;
  m.fluid_mesh = stats;
  m.converged = true;
  m.status = "converged";
  Json& j = r.summary;
  j = summary_header(c);
  j["mesh"] = {{"fluid", to_json(stats)}};
  add_measures(j, m);
  j["obstacles"] = obstacle_forces_json(c, f);
  j["fluid"] = fluid_json(*f.stokes);
  r.report = fluid_report(c, *f.stokes, stats, j["obstacles"]);
  auto files = [&](RunOutputs& out) {
    ScopedPhase phase(times, "output");
    if (c.output.vtu)
      out.write("fluid.vtu", [&](const std::string& p) {
        write_fluid_vtu(p, c, *f.mesh, *fluid, f.stokes->last_solution_chi());
      });
    if (c.output.png)
      out.write("fluid.png", [&](const std::string& p) {
        write_fluid_png(p, c, *f.mesh, *fluid, Mesh{}, {}, c.name + ": fluid velocity magnitude (no structure)",
                        "hF = " + shortest(c.fluid->h) + ";  no structure");
      });
    out.write("case.toml", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << to_toml(c); }); });
  };
  write_outputs(c, r, files, [&](Json& summary) { finish_timing(summary, r.measures, times, total); });
  return r;
}

}  // namespace fsi
