// What every time run (SPEC §12) does around its steps, whatever it marches: the
// output directory it writes into while it solves (its frames and checkpoints), when
// a frame and a checkpoint are due, and the checkpoint it was resumed from.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

class TimeRun {
 public:
  TimeRun(const Case& c, const char* kind) : c_(c), time_(*c.time), kind_(kind) {}

  void resume(Checkpoint k) { resumed_ = std::move(k); }
  const Checkpoint* resumed() const { return resumed_ ? &*resumed_ : nullptr; }
  // The last frame the checkpoint lists (−1: none; nullopt: not resumed): the resumed
  // run keeps the frame files up to it, and removes the rest (an interrupted run's last
  // state, written beside the series, and what it wrote after its checkpoint).
  std::optional<int> resumed_frames_to() const;
  int first_step() const { return resumed_ ? resumed_->step + 1 : 1; }
  // summary.json's "resumed": the directory, step and time continued from (null: none).
  Json resumed_json(const std::string& dir) const;

  void open(RunOutputs& out) { out_ = &out; }
  RunOutputs* out() const { return out_; }

  // After step k: a frame every time.output_every steps and at the last; a checkpoint
  // every time.checkpoint_every steps (0: none but the final one).
  bool frame_due(int k) const { return k % time_.output_every == 0 || k == time_.steps(); }
  bool checkpoint_due(int k) const { return time_.checkpoint_every > 0 && k % time_.checkpoint_every == 0; }
  // checkpoint.bin, atomically, after `step` steps at time t, its arrays from fill(k).
  void write_checkpoint(int step, double t, const std::function<void(Checkpoint&)>& fill) const;

 private:
  const Case& c_;
  TimeParams time_;
  const char* kind_;
  std::optional<Checkpoint> resumed_;
  RunOutputs* out_ = nullptr;
};

}  // namespace fsi
