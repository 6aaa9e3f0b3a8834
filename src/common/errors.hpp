// Error kinds, each mapped to an exit status in app/ (SPEC §8).
#pragma once

#include <stdexcept>
#include <string>

namespace fsi {

// Invalid input (case file, override, mesh file): exit status 2, nothing written.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A solver failed during a run (QP, factorisation, NaN): exit status 1.
struct SolverFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A file could not be written (full disk, lost permission): exit status 1. The
// message names the path and the system's reason (strerror).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
  // "cannot write <path>: <strerror(err)>"
  OutputError(const std::string& path, int err);
};

}  // namespace fsi
