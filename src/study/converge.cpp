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
#include "run/outputs/output_dir.hpp"
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
  if (o.refine != "all" && o.refine != "fluid" && o.refine != "structure")
    throw InputError("--refine \"" + o.refine + "\" is not known; allowed: all, fluid, structure");
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
      if (spec.c.structure.shape != "none") cache.structure_mesh(spec.c);
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
  for (const Restart& r : study.restarts)
    if (r.run.result.exit_status > 128) return interrupted_exit_status();
  if (study.penalty_check.result.exit_status > 128) return interrupted_exit_status();
  return status;
}

std::vector<std::string> level_dirs(const std::vector<LevelSpec>& specs) {
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(std::filesystem::path(s.c.output.dir).filename().string());
  return names;
}

// One run of a study: its case with the study's set-up cache, from `start` (null: at
// rest), progress lines prefixed; its result, wall time and status in `run`.
void run_one(LevelRun& run, SetupCache& cache, const ConvergeOptions& options, const std::string& prefix,
             const Eigen::VectorXd* start = nullptr) {
  RunOptions run_options;
  run_options.cache = &cache;
  run_options.initial_displacement = start;
  if (options.progress) run_options.progress = [&, prefix](const std::string& l) { options.progress(prefix + l); };
  run_options.keep_fields = options.keep_fields && options.on_run;
  const Stopwatch clock;
  run.result = run_case(run.spec.c, run_options);
  run.wall_s = clock.elapsed();
  run.status = status_of(run.result);
  if (options.on_run) options.on_run(run.spec.c.output.dir, run.result);
  run.result.fields = {};
}

// Runs the levels coarsest first, each level's schemes together (they share its meshes
// and set-ups); stops between runs on Ctrl-C or SIGTERM.
void run_levels(Study& study, SetupCache& cache, const ConvergeOptions& options) {
  for (LevelRun& run : study.runs) {
    if (interrupt_requested()) break;
    const std::string prefix = "[level " + std::to_string(run.spec.index) + "/" + std::to_string(study.levels) +
                               (study.schemes.size() > 1 ? ", " + run.spec.scheme : "") + "] ";
    run_one(run, cache, options, prefix);
    if (options.progress) options.progress(prefix + run.result.report + " (" + approx(run.wall_s, 3) + " s)");
  }
}

// Where a scheme ended apart from the study's own at a level (max |u| beyond
// agreement_allowed), it is rerun from the study's end state (issue 12, item 5).
void run_restarts(Study& study, SetupCache& cache, const ConvergeOptions& options) {
  if (study.schemes.size() < 2 || study.quantities.empty()) return;
  const QuantityStudy& q = study.quantities.front();  // max |u|
  const double allowed = agreement_allowed(q);
  const std::vector<const LevelRun*> primary = runs_of(study, study.schemes.front());
  for (std::size_t s = 1; s < study.schemes.size(); ++s) {
    const std::vector<const LevelRun*> other = runs_of(study, study.schemes[s]);
    for (std::size_t i = 0; i < other.size() && i < primary.size(); ++i) {
      if (interrupt_requested()) return;
      if (other[i]->status != "converged" || primary[i]->status != "converged") continue;
      const double own = q.quantity.read(other[i]->result.summary), start = q.values[i];
      if (!(std::abs(own - start) > allowed) || primary[i]->result.displacement.size() == 0) continue;
      Restart r;
      r.from = study.schemes.front();
      r.run.spec = other[i]->spec;
      r.run.spec.c.output.dir += "-restart";
      r.start = start, r.own = own;
      const std::string prefix = "[level " + std::to_string(r.run.spec.index) + "/" + std::to_string(study.levels) +
                                 ", " + r.run.spec.scheme + " from " + r.from + "'s end state] ";
      run_one(r.run, cache, options, prefix, &primary[i]->result.displacement);
      r.value = r.run.result.summary.is_null() ? NAN : q.quantity.read(r.run.result.summary);
      judge_restart(r, allowed);
      if (options.progress) options.progress(prefix + r.verdict);
      study.restarts.push_back(std::move(r));
    }
  }
}

// The finest level of the study's scheme once more, on its meshes, with ε·r²
// (study/penalty_error.hpp): penalised fluid only, and not when only the structure
// is refined (ε then does not move with the levels, and the fluid's error is not
// the study's subject).
void run_penalty_check(Study& study, SetupCache& cache, const ConvergeOptions& options) {
  const std::vector<const LevelRun*> primary = runs_of(study, study.schemes.front());
  const LevelRun& finest = *primary.back();
  const Case& c = finest.spec.c;
  if (!c.fluid || c.fluid->method != "penalised" || study.refine == "structure" || c.structure.shape == "none" ||
      interrupt_requested())
    return;  // no structure: no penalty
  LevelRun& check = study.penalty_check;
  check.spec = finest.spec;
  check.spec.scheme = "eps-check";
  check.spec.c.coupling.eps = c.coupling.eps * study.ratio * study.ratio;
  check.spec.c.coupling.eps_rule = "fixed";  // ε as given, off the layer rule's
  check.spec.c.output.dir += "-eps";
  // The check is measured, not looked at: without pictures its fluid stays on the
  // near region (no far-field expansion), and that region is the finest level's.
  check.spec.c.output.png = check.spec.c.output.vtu = false;
  if (finest.status != "converged") {
    check.status = "not run: the finest level did not converge";
    return;
  }
  const std::string prefix = "[penalty check: level " + std::to_string(finest.spec.index) + ", ε = " +
                             approx(check.spec.c.coupling.eps, 3) + "] ";
  run_one(check, cache, options, prefix, &finest.result.displacement);  // warm: the same meshes, a nearby state
  if (options.progress) options.progress(prefix + check.result.report + " (" + approx(check.wall_s, 3) + " s)");
}

// converge's default ε rule for a penalised case that states none: "layer" (the
// Brinkman layer resolved at every level, io/case.hpp), as overrides of every level.
// Not for the fluid alone: without a structure χ = 0 and ε plays no part.
std::vector<std::string> with_default_eps_rule(const Case& base, std::vector<std::string> overrides,
                                               const ConvergeOptions& options) {
  if (!base.fluid || base.fluid->method != "penalised" || base.coupling.eps_rule_given ||
      base.structure.shape == "none")
    return overrides;
  const double eps = layer_eps(base.fluid->mu, base.fluid->size_near());
  overrides.push_back("coupling.eps_rule=layer");
  overrides.push_back("coupling.eps=" + shortest(eps));
  if (options.progress)
    options.progress("[eps] coupling.eps_rule = \"layer\" (converge's default for a penalised case stating no rule): "
                     "ε = " + approx(eps, 4) + " on level 1, / r² per level" +
                     (base.coupling.eps_given ? " (the case's ε = " + approx(base.coupling.eps, 4) +
                                                    " is not used; --set coupling.eps_rule=fixed keeps it)"
                                              : std::string()));
  return overrides;
}

}  // namespace

ConvergeResult run_convergence(const CaseSource& source, const ConvergeOptions& options) {
  check_options(options);
  const Case base = source.load(options.overrides);
  if (options.refine == "fluid" && !base.fluid)
    throw InputError("--refine fluid: " + base.source + " has no fluid to refine; allowed: all or structure");
  // structure.shape = "none": the fluid alone, its quantities the obstacles' forces
  // (SPEC §10: the DFG benchmark's drag and lift), the fluid's meshes refined.
  ConvergeResult result;
  result.out_dir = options.out_dir.empty() ? "out/" + base.name + "-converge" : options.out_dir;
  check_output_dir(result.out_dir, options.out_dir.empty() ? base.source + " (name)" : "--out");
  const std::vector<std::string> overrides = with_default_eps_rule(base, options.overrides, options);
  std::vector<LevelSpec> specs = make_levels(source, overrides, options.levels, options.ratio,
                                             options.schemes, result.out_dir, options.refine);
  std::stable_sort(specs.begin(), specs.end(), [](const LevelSpec& a, const LevelSpec& b) { return a.index < b.index; });
  SetupCache cache;
  const Stopwatch meshing;
  check_level_meshes(specs, cache);  // every level's meshes, built once for the study
  const double meshing_s = meshing.elapsed();
  if (options.progress)
    options.progress("[meshes] every level's meshes built and checked in " + approx(meshing_s, 3) + " s");
  const Stopwatch running;

  Study study;
  study.ratio = options.ratio;
  study.levels = options.levels;
  study.refine = options.refine;
  study.schemes = options.schemes.empty() ? std::vector<std::string>{base.coupling.scheme} : options.schemes;
  if (!base.fluid || base.structure.shape == "none") study.schemes.resize(1);  // nothing coupled to compare
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
  run_penalty_check(study, cache, options);

  evaluate(study, base);
  run_restarts(study, cache, options);
  result.report = convergence_markdown(study);
  out.write("convergence.csv", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << convergence_csv(study); }); });
  out.write("convergence.md", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << result.report; }); });
  out.write("convergence.png", [&](const std::string& p) { write_convergence_png(p, study); });
  result.exit_status = exit_status_of(study);
  Json summary = header;
  summary.update(convergence_json(study));
  // The levels' own timing_s.mesh is ~0: their meshes were built here, up front.
  summary["timing_s"] = {{"meshes", meshing_s}, {"runs", running.elapsed()}};
  summary["status"] = result.exit_status == 0 ? "converged" : result.exit_status == 1 ? "failed"
                      : result.exit_status == 3                                  ? "iteration limit"
                                                                                 : "interrupted";
  result.summary = out.finish(summary);
  if (out.failed()) result.exit_status = 1;
  return result;
}

}  // namespace fsi
