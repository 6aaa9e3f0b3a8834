// One phase of a fixed-point pass, run so that what a phase is expected to meet (a
// solver's failure: a SolverFailure or a QpError; memory running out) ends the loop
// as a SolverFailure naming the phase and the pass. Anything else (std::logic_error,
// std::invalid_argument, std::out_of_range from our own code) is a bug: it
// propagates, not reported as a failed solve. Shared by the coupling loops.
#pragma once

#include <new>
#include <string>

#include "common/errors.hpp"
#include "qp/qp_problem.hpp"

namespace fsi {

template <class Phase>
auto guarded(const std::string& phase, int iteration, Phase&& run) -> decltype(run()) {
  auto fail = [&](const std::string& what) {
    return SolverFailure(phase + " failed at fixed-point iteration " + std::to_string(iteration) +
                         ": " + what);
  };
  try {
    return run();
  } catch (const SolverFailure& e) {
    throw fail(e.what());
  } catch (const QpError& e) {
    throw fail(e.what());
  } catch (const std::bad_alloc&) {
    throw fail("out of memory");
  }
}

}  // namespace fsi
