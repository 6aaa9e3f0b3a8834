// The progress line of a time run (SPEC §12): the step, the simulated time, the pace
// and the time left at that pace, at most every 2 s (and at the last step), on the
// run's progress callback (stderr, also when it is not a terminal).
#pragma once

#include <cstdio>
#include <functional>
#include <string>

#include "common/timer.hpp"

namespace fsi {

class TimeProgress {
 public:
  explicit TimeProgress(std::function<void(const std::string&)> progress) : progress_(std::move(progress)) {}
  // A resumed run's first step is first + 1: its pace counts the steps it took.
  void start_after(int first) { first_ = first; }
  // After step k of `steps`, at simulated time t.
  void report(int k, int steps, double t) {
    if (!progress_) return;
    const double elapsed = clock_.elapsed();
    if (k < steps && elapsed - last_ < 2.0) return;
    last_ = elapsed;
    const double rate = (k - first_) / (elapsed > 1e-9 ? elapsed : 1e-9);
    char text[160];
    std::snprintf(text, sizeof text, "[time] step %d/%d, t = %.6g s, %.3g steps/s, about %.0f s left", k, steps, t,
                  rate, (steps - k) / rate);
    progress_(text);
  }

 private:
  std::function<void(const std::string&)> progress_;
  Stopwatch clock_;
  double last_ = 0;
  int first_ = 0;
};

}  // namespace fsi
