// Runs one case end to end: meshes, solves, writes summary.json and the pictures.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "common/fault.hpp"
#include "common/timer.hpp"
#include "io/case.hpp"
#include "run/run_measures.hpp"
#include "run/summary.hpp"

namespace fsi {

class SetupCache;

struct RunOptions {
  std::function<void(const std::string&)> progress;  // one line per solver iteration
  SetupCache* cache = nullptr;  // reuse meshes and setups across runs (sweeps)
  // The coupled run's u⁰ (FixedPointCoupling::initial); null: the structure at rest.
  const Eigen::VectorXd* initial_displacement = nullptr;
};

struct RunResult {
  // SPEC §8: 0 converged, 1 failed, 3 iteration limit; 128 + signal if stopped by
  // SIGINT / SIGTERM / SIGHUP.
  int exit_status = 0;
  Json summary;
  RunMeasures measures;  // what summary.json's headline keys were written from
  std::string report;   // a paragraph for the user (the numbers, even after a failure)
  std::string failure;  // exit status 1: what failed, naming the phase
  Eigen::VectorXd displacement;  // the final ũ (2nv; empty if none): a restart's u⁰
};

// Checks the output directory and the meshes against the case (InputError, exit 2:
// nothing is written), then solves and writes. A failure after that never escapes
// as an exception: summary.json says "status": "failed" with the message (and the
// last good state where there is one) and the result has exit status 1.
RunResult run_case(const Case& c, const RunOptions& options);

// The contact-only problem of SPEC §2 (a case without [fluid]).
RunResult run_contact_case(const Case& c, const RunOptions& options);

// The coupled problem of SPEC §5; with coupling.max_iterations = 0 the fluid alone
// around the structure at rest.
RunResult run_fsi_case(const Case& c, const RunOptions& options);

// structure.shape = "none" (run_fsi_case calls it): the fluid alone, no structure, and
// the fluid's force on each obstacle.
RunResult run_fluid_case(const Case& c, const RunOptions& options);

// The same with fluid.method = "body-fitted" (run_fsi_case calls it): the fluid
// remeshed around the deformed structure each pass, for configurations without contact.
RunResult run_body_fitted_case(const Case& c, const RunOptions& options);

// summary.json's first keys: name, problem ("contact", "fluid", "fsi"), parameters.
Json summary_header(const Case& c);

// make() timed as the phase `name` of `times`, then the fault-injection point of that
// name (tests make a phase fail there): one set-up step of a run.
template <class Make>
auto in_phase(PhaseTimes& times, const char* name, Make&& make) {
  ScopedPhase phase(times, name);
  auto made = make();
  fault_point(name);
  return made;
}

class RunOutputs;
// Writes the run's directory (run/output_dir.hpp): summary.json as "writing", then
// `files`, then r.summary after `finalise` (the output phase's timing). A failed
// write turns r into a failure (exit status 1) naming the file and the reason; the
// report keeps the numbers.
void write_outputs(const Case& c, RunResult& r, const std::function<void(RunOutputs&)>& files,
                   const std::function<void(Json&)>& finalise);

}  // namespace fsi
