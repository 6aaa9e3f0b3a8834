#include "run/run_case.hpp"

#include <new>
#include <optional>

#include "common/errors.hpp"
#include "io/output_path.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/problem_kinds.hpp"
#include "run/time_checkpoint.hpp"

namespace fsi {
namespace {

// A failure before any state worth keeping (meshing, set-up, the contact-only QP):
// summary.json carries the inputs and the message.
RunResult failed_run(const Case& c, const char* kind, const std::string& failure) {
  RunResult r;
  r.exit_status = 1;
  r.failure = failure;
  r.report = c.name + ": failed: " + failure;
  r.measures.failure = failure;  // and status "failed", nothing measured
  Json j = summary_header(c, kind);
  j["converged"] = false;
  j["status"] = "failed";
  j["failure"] = failure;  // no "iterations": none ran to the end
  r.summary = j;
  try {
    RunOutputs out(c.output.dir);
    out.begin(j);
    out.finish(j);
  } catch (const OutputError& e) {
    r.failure += "; summary.json not written: " + std::string(e.what());
  }
  return r;
}

void fail_writing(RunResult& r, const std::string& what) {
  r.exit_status = 1;
  r.failure = (r.failure.empty() ? "" : r.failure + "; ") + "writing the outputs: " + what;
}

// The run's directory (run/outputs/output_dir.hpp): summary.json as "writing", then the
// problem's files (the "output" phase), then r.summary with its "timing_s". A failed
// write turns r into a failure (exit status 1) naming the file and the reason; the
// report keeps the numbers.
void write_outputs(Problem& problem, const Case& c, RunResult& r, PhaseTimes& times, const Stopwatch& total,
                   RunOutputs* opened) {
  RunOutputs fresh(c.output.dir);
  RunOutputs& out = opened ? *opened : fresh;
  try {
    if (!opened) out.begin(summary_header(c, problem.kind()));
    {
      ScopedPhase phase(times, "output");
      problem.write(out);
    }
    finish_timing(r.summary, r.measures, times, total);
    r.summary = out.finish(r.summary);
  } catch (const OutputError& e) {
    fail_writing(r, e.what());
    return;
  }
  if (out.failed()) fail_writing(r, out.failure());
}

RunResult run_steps(Problem& problem, const Case& c, bool keep_fields) {
  PhaseTimes times;
  const Stopwatch total;
  problem.set_up(times);
  std::optional<RunOutputs> streamed;
  if (problem.streams()) {
    streamed.emplace(c.output.dir);
    streamed->begin(summary_header(c, problem.kind()), problem.resumed_frames_to());
    problem.open(*streamed);
  }
  problem.solve(times);
  RunResult r;
  problem.measure(r);
  problem.summarise(r);
  write_outputs(problem, c, r, times, total, streamed ? &*streamed : nullptr);
  if (keep_fields) {
    try {
      problem.final_fields(r.fields);
    } catch (const std::bad_alloc&) {
      r.fields = {};  // the run and its files stand; its arrays are an extra it cannot afford
    }
  }
  return r;
}

}  // namespace

Json summary_header(const Case& c, const char* kind) {
  Json j;
  j["name"] = c.name;
  j["problem"] = kind;
  j["parameters"] = to_json(c);
  return j;
}

RunResult run(Problem& problem, const Case& c, bool keep_fields) {
  try {
    return run_steps(problem, c, keep_fields);
  } catch (const InputError&) {
    throw;  // found before anything was written
  } catch (const SolverFailure& e) {
    return failed_run(c, problem.kind(), e.what());
  } catch (const OutputError& e) {
    return failed_run(c, problem.kind(), e.what());
  } catch (const std::bad_alloc&) {
    return failed_run(c, problem.kind(), "out of memory");
  } catch (const std::exception& e) {
    return failed_run(c, problem.kind(), std::string("internal error: ") + e.what());
  }
}

// Only time kinds resume, and run_case refuses --resume for a case without [time]
// before it reaches here (an InputError naming the case).
void Problem::resume(Checkpoint k) {
  throw std::logic_error(k.source + ": a steady kind of run was asked to resume");
}

RunResult run_case(const Case& c, const RunOptions& options) {
  check_output_dir(c.output.dir, c.output.dir_origin);
  const std::unique_ptr<Problem> problem = make_problem(c, options);
  if (!options.resume_dir.empty()) {
    if (!c.time) throw InputError("--resume " + options.resume_dir + ": " + c.source + " has no [time] section to resume");
    problem->resume(read_resume_checkpoint(options.resume_dir, c, problem->kind()));
  }
  return run(*problem, c, options.keep_fields);
}

}  // namespace fsi
