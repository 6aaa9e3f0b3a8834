// A time run's frames (SPEC §12) written as they are computed: each frame's file goes
// into the run's directory at once and its collection NAME.pvd (each file with its
// time) is rewritten with it, so that ParaView can follow a running run, a run
// stopped even by SIGKILL keeps what it wrote, and memory does not grow with the
// frames. A resumed run takes the series back from its checkpoint and continues it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "run/outputs/output_dir.hpp"

namespace fsi {

class FrameSeries {
 public:
  // "structure": structure-NNNNNN.vtu (N the step) listed in structure.pvd; with
  // extension ".png", pictures frame-NNNNNN.png (no collection: the animation's).
  explicit FrameSeries(std::string name, std::string extension = ".vtu")
      : name_(std::move(name)), extension_(std::move(extension)) {}

  // Writes step's frame through write(path), then the collection; a failed write is
  // recorded by `out` (the frame is then not listed). False if it failed.
  bool add(RunOutputs& out, int step, double t, const std::function<void(const std::string& path)>& write);
  // NAME.pvd for the frames so far (a resumed run that writes no new frame needs it);
  // nothing for pictures.
  bool write_collection(RunOutputs& out) const;
  bool empty() const { return steps_.empty(); }
  std::size_t size() const { return steps_.size(); }
  int last_step() const { return steps_.empty() ? -1 : steps_.back(); }
  std::string file_name(int step) const;
  std::vector<std::string> file_names() const;

  void save(Checkpoint& k) const;
  void restore(const Checkpoint& k);

 private:
  std::string name_, extension_;
  std::vector<int> steps_;
  std::vector<double> times_;
};

}  // namespace fsi
