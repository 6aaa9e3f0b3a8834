// Runs one case end to end: meshes, solves, writes summary.json and the pictures.
#pragma once

#include <functional>
#include <string>

#include "io/case.hpp"
#include "run/summary.hpp"

namespace fsi {

class SetupCache;

struct RunOptions {
  std::function<void(const std::string&)> progress;  // one line per solver iteration
  SetupCache* cache = nullptr;  // reuse meshes and setups across runs (sweeps)
};

struct RunResult {
  int exit_status = 0;  // 0 converged, 3 iteration limit reached (SPEC §8)
  Json summary;
  std::string report;   // a paragraph for the user
};

// Throws InputError (exit 2) or SolverFailure (exit 1).
RunResult run_case(const Case& c, const RunOptions& options);

// The contact-only problem of SPEC §2 (a case without [fluid]).
RunResult run_contact_case(const Case& c, const RunOptions& options);

// The coupled problem of SPEC §5; with coupling.max_iterations = 0 the fluid alone
// around the structure at rest.
RunResult run_fsi_case(const Case& c, const RunOptions& options);

}  // namespace fsi
