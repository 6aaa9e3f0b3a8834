#include "run/outputs/frame_series.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "io/vtu.hpp"

namespace fsi {

std::string FrameSeries::file_name(int step) const {
  char number[16];
  std::snprintf(number, sizeof number, "-%06d", step);
  return name_ + number + extension_;
}

std::vector<std::string> FrameSeries::file_names() const {
  std::vector<std::string> names;
  for (int step : steps_) names.push_back(file_name(step));
  return names;
}

bool FrameSeries::add(RunOutputs& out, int step, double t, const std::function<void(const std::string&)>& write) {
  if (!out.write(file_name(step), write)) return false;
  steps_.push_back(step), times_.push_back(t);
  return write_collection(out);
}

bool FrameSeries::write_collection(RunOutputs& out) const {
  if (extension_ != ".vtu") return true;
  return out.write(name_ + ".pvd", [&](const std::string& path) {
    std::vector<PvdEntry> entries;
    for (std::size_t i = 0; i < steps_.size(); ++i) entries.push_back({file_name(steps_[i]), 0, times_[i]});
    write_pvd(path, entries);
  });
}

void FrameSeries::save(Checkpoint& k) const {
  k.put_ints(name_ + ".frames.step", steps_);
  k.put(name_ + ".frames.t", Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(times_.data(), long(times_.size()))));
}

void FrameSeries::restore(const Checkpoint& k) {
  steps_ = k.ints(name_ + ".frames.step");
  const Eigen::VectorXd& t = k.vector(name_ + ".frames.t", long(steps_.size()));
  times_.assign(t.data(), t.data() + t.size());
  if (!steps_.empty() && steps_.back() > k.step)
    throw InputError(k.source + ": a frame after its step (a damaged checkpoint)");
}

}  // namespace fsi
