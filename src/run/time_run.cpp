#include "run/time_run.hpp"

#include <algorithm>

#include "run/time_checkpoint.hpp"

namespace fsi {

Json TimeRun::resumed_json(const std::string& dir) const {
  if (!resumed_) return nullptr;
  return {{"from", dir}, {"step", resumed_->step}, {"t", resumed_->t}};
}

std::optional<int> TimeRun::resumed_frames_to() const {
  if (!resumed_) return std::nullopt;
  int last = -1;
  const std::string suffix = ".frames.step";
  for (const auto& [name, steps] : resumed_->arrays())
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
        steps.size())
      last = std::max(last, int(steps[steps.size() - 1]));
  return last;
}

void TimeRun::write_checkpoint(int step, double t, const std::function<void(Checkpoint&)>& fill) const {
  if (!out_) return;
  Checkpoint k = new_checkpoint(c_, kind_, step, t);
  fill(k);
  out_->write(checkpoint_file_name(), [&](const std::string& path) { fsi::write_checkpoint(path, k); });
}

}  // namespace fsi
