// Error kinds, each mapped to an exit status in app/ (SPEC §8).
#pragma once

#include <stdexcept>

namespace fsi {

// Invalid input (case file, override, mesh file): exit status 2, nothing written.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A solver failed during a run (QP, factorisation, NaN): exit status 1.
struct SolverFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fsi
