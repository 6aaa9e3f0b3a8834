// Runs one case end to end: meshes, solves, writes summary.json and the pictures.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "common/fault.hpp"
#include "common/timer.hpp"
#include "io/case.hpp"
#include "run/problem.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/run_measures.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

class SetupCache;

struct RunOptions {
  std::function<void(const std::string&)> progress;  // one line per solver iteration
  SetupCache* cache = nullptr;  // reuse meshes and setups across runs (sweeps)
  // The coupled run's u⁰ (FixedPointCoupling::initial); null: the structure at rest.
  const Eigen::VectorXd* initial_displacement = nullptr;
  // A time run continued from this directory's checkpoint (`fsicontact run --resume`);
  // empty: from t = 0. The case's output.dir must be this directory.
  std::string resume_dir;
  // RunResult::fields filled (the Python module); the fluid is then completed beyond
  // the region a substructured solve left exact, as for fluid.vtu.
  bool keep_fields = false;
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
  FinalFields fields;            // RunOptions::keep_fields: the final state's fields
};

// Checks the output directory and the meshes against the case (InputError, exit 2:
// nothing is written), then solves and writes: run(*make_problem(c, options), c,
// options.keep_fields).
RunResult run_case(const Case& c, const RunOptions& options);

// set_up → solve → measure → summarise → write (run/problem.hpp), each phase timed;
// summary.json's "timing_s" holds them. A failure after validation never escapes as
// an exception: summary.json says "status": "failed" with the message (and the last
// good state where there is one) and the result has exit status 1.
// keep_fields: r.fields from Problem::final_fields after the files are written.
RunResult run(Problem& problem, const Case& c, bool keep_fields = false);

// summary.json's first keys: name, problem (Problem::kind), parameters.
Json summary_header(const Case& c, const char* kind);

// make() timed as the phase `name` of `times`, then the fault-injection point of that
// name (tests make a phase fail there): one set-up step of a run.
template <class Make>
auto in_phase(PhaseTimes& times, const char* name, Make&& make) {
  ScopedPhase phase(times, name);
  auto made = make();
  fault_point(name);
  return made;
}


}  // namespace fsi
