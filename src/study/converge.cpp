#include "study/converge.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "run/output_dir.hpp"
#include "run/setup_cache.hpp"
#include "study/convergence_report.hpp"

namespace fsi {
namespace {

void check_options(const ConvergeOptions& o) {
  if (o.levels < 3 || o.levels > 10)
    throw InputError("--levels " + std::to_string(o.levels) + " is out of range; allowed: 3 to 10 (three levels "
                     "give an order, four test the asymptotic range)");
  if (!(o.ratio > 1 && o.ratio <= 10))
    throw InputError("--ratio " + shortest(o.ratio) + " is out of range; allowed: (1, 10] (each level's sizes are "
                     "the previous ones divided by it)");
  std::set<std::string> seen;
  for (const auto& s : o.schemes) {
    if (s != "constant" && s != "aitken" && s != "iqn-ils")
      throw InputError("--schemes: \"" + s + "\" is not a known scheme; allowed: constant, aitken, iqn-ils");
    if (!seen.insert(s).second) throw InputError("--schemes: \"" + s + "\" appears twice; allowed: each scheme once");
  }
}

// Every level's meshes built (kept in the cache for the runs) and checked against its
// case before anything is written; a failure to mesh valid geometry is left to that
// level's run, which records it.
void check_level_meshes(const std::vector<LevelSpec>& specs, SetupCache& cache) {
  for (const LevelSpec& spec : specs) {
    try {
      cache.structure_mesh(spec.c);
      if (spec.c.fluid && spec.c.fluid->method == "penalised") cache.fluid_mesh(spec.c);  // body-fitted: remeshed per pass
    } catch (const InputError& e) {
      throw InputError("level " + std::to_string(spec.index) + ": " + e.what());
    } catch (const SolverFailure&) {
    }
  }
}

std::string status_of(const RunResult& r) {
  if (r.exit_status == 1) return "failed: " + r.failure;
  if (r.exit_status > 128) return "interrupted";
  if (r.exit_status == 3) return "not converged";
  return "converged";
}

int exit_status_of(const Study& study) {
  int status = 0;
  for (const LevelRun& r : study.runs) {
    if (r.result.exit_status > 128 || r.status == "not run") return interrupted_exit_status();
    if (r.result.exit_status == 1) status = 1;
    else if (r.result.exit_status == 3 && status == 0) status = 3;
  }
  return status;
}

std::vector<std::string> level_dirs(const std::vector<LevelSpec>& specs) {
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(std::filesystem::path(s.c.output.dir).filename().string());
  return names;
}

// Runs the levels coarsest first, each level's schemes together (they share its meshes
// and set-ups); stops between runs on Ctrl-C or SIGTERM.
void run_levels(Study& study, SetupCache& cache, const ConvergeOptions& options) {
  for (LevelRun& run : study.runs) {
    if (interrupt_requested()) break;
    const std::string prefix = "[level " + std::to_string(run.spec.index) + "/" + std::to_string(study.levels) +
                               (study.schemes.size() > 1 ? ", " + run.spec.scheme : "") + "] ";
    RunOptions run_options;
    run_options.cache = &cache;
    if (options.progress) run_options.progress = [&, prefix](const std::string& l) { options.progress(prefix + l); };
    const Stopwatch clock;
    run.result = run_case(run.spec.c, run_options);
    run.wall_s = clock.elapsed();
    run.status = status_of(run.result);
    if (options.progress) options.progress(prefix + run.result.report + " (" + approx(run.wall_s, 3) + " s)");
  }
}

}  // namespace

ConvergeResult run_convergence(const std::string& case_path, const ConvergeOptions& options) {
  check_options(options);
  const Case base = load_case(case_path, options.overrides);
  ConvergeResult result;
  result.out_dir = options.out_dir.empty() ? "out/" + base.name + "-converge" : options.out_dir;
  check_output_dir(result.out_dir, options.out_dir.empty() ? base.source + " (name)" : "--out");
  std::vector<LevelSpec> specs = make_levels(case_path, options.overrides, options.levels, options.ratio,
                                             options.schemes, result.out_dir);
  std::stable_sort(specs.begin(), specs.end(), [](const LevelSpec& a, const LevelSpec& b) { return a.index < b.index; });
  SetupCache cache;
  check_level_meshes(specs, cache);

  Study study;
  study.ratio = options.ratio;
  study.levels = options.levels;
  study.schemes = options.schemes.empty() ? std::vector<std::string>{base.coupling.scheme} : options.schemes;
  if (!base.fluid) study.schemes.resize(1);
  for (auto& spec : specs) {
    LevelRun run;
    run.spec = std::move(spec);
    study.runs.push_back(std::move(run));
  }

  RunOutputs out(result.out_dir);  // nothing was written so far
  Json header = {{"name", base.name}, {"problem", "convergence"}, {"parameters", to_json(base)}};
  out.begin(header);
  remove_stale_subdirs(result.out_dir, "level-", level_dirs(specs));
  run_levels(study, cache, options);

  evaluate(study, base.fluid.has_value());
  result.report = convergence_markdown(study);
  out.write("convergence.csv", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << convergence_csv(study); }); });
  out.write("convergence.md", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << result.report; }); });
  out.write("convergence.png", [&](const std::string& p) { write_convergence_png(p, study); });
  result.exit_status = exit_status_of(study);
  Json summary = header;
  summary.update(convergence_json(study));
  summary["status"] = result.exit_status == 0 ? "converged" : result.exit_status == 1 ? "failed"
                      : result.exit_status == 3                                  ? "iteration limit"
                                                                                 : "interrupted";
  result.summary = out.finish(summary);
  if (out.failed()) result.exit_status = 1;
  return result;
}

}  // namespace fsi
