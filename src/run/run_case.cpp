#include "run/run_case.hpp"

#include <new>

#include "common/errors.hpp"
#include "io/output_path.hpp"
#include "run/output_dir.hpp"

namespace fsi {
namespace {

// A failure before any state worth keeping (meshing, set-up, the contact-only QP):
// summary.json carries the inputs and the message.
RunResult failed_run(const Case& c, const std::string& failure) {
  RunResult r;
  r.exit_status = 1;
  r.failure = failure;
  r.report = c.name + ": failed: " + failure;
  r.measures.failure = failure;  // and status "failed", nothing measured
  Json j = summary_header(c);
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

}  // namespace

Json summary_header(const Case& c) {
  Json j;
  j["name"] = c.name;
  j["problem"] = !c.fluid ? "contact" : c.coupling.max_iterations == 0 || c.structure.shape == "none" ? "fluid" : "fsi";
  j["parameters"] = to_json(c);
  return j;
}

void write_outputs(const Case& c, RunResult& r, const std::function<void(RunOutputs&)>& files,
                   const std::function<void(Json&)>& finalise) {
  RunOutputs out(c.output.dir);
  try {
    out.begin(summary_header(c));
    files(out);
    finalise(r.summary);
    r.summary = out.finish(r.summary);
  } catch (const OutputError& e) {
    fail_writing(r, e.what());
    return;
  }
  if (out.failed()) fail_writing(r, out.failure());
}

RunResult run_case(const Case& c, const RunOptions& options) {
  check_output_dir(c.output.dir, c.output.dir_origin);
  try {
    return c.fluid ? run_fsi_case(c, options) : run_contact_case(c, options);
  } catch (const InputError&) {
    throw;  // found before anything was written
  } catch (const SolverFailure& e) {
    return failed_run(c, e.what());
  } catch (const OutputError& e) {
    return failed_run(c, e.what());
  } catch (const std::bad_alloc&) {
    return failed_run(c, "out of memory");
  } catch (const std::exception& e) {
    return failed_run(c, std::string("internal error: ") + e.what());
  }
}

}  // namespace fsi
