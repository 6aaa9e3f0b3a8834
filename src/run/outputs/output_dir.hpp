// The files of one run in its output directory (docs/cases.md, "What a run writes"). The
// directory is created at the first write, after validation and the solve; it then
// holds either one run's files or a summary.json that says "writing": begin() marks
// it so before anything else and removes what an earlier run left there (its
// outputs, and the temporaries a SIGKILL may leave), so that a reader never takes
// the files of two runs for one. A write that fails (a full disk) is recorded, the
// other files and the summary still get their chance, and the summary says which
// file failed and why.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

// Every file name a run or a sweep writes into its directory.
const std::vector<std::string>& output_file_names();

// Removes `dir`'s files named in output_file_names() but `keep`, a time run's frames
// (fluid-NNNNNN.vtu, structure-NNNNNN.vtu, frame-NNNNNN.png) but those of steps up to
// `keep_frames_to`, checkpoint.bin if `keep_checkpoint` (a resumed run's, which it
// continues), and their temporaries;
// nothing else (a user's own files stay).
void remove_stale_outputs(const std::string& dir, const std::string& keep = "", int keep_frames_to = -1,
                          bool keep_checkpoint = false);
// The step of a time run's frame file name, −1 for any other name.
int frame_step(const std::string& file_name);

// Subdirectories of `dir` named `prefix`… (an earlier sweep's row-NN, an earlier
// study's level-N) that are not in `keep`: their files of ours removed, then the
// directory itself if that left it empty (a user's own files stay).
void remove_stale_subdirs(const std::string& dir, const std::string& prefix, const std::vector<std::string>& keep);

class RunOutputs {
 public:
  explicit RunOutputs(std::string dir) : dir_(std::move(dir)) {}

  // Creates the directory, writes summary.json = header + {"status": "writing"} and
  // removes stale outputs. Throws OutputError (path and strerror) if it cannot.
  // A resumed time run (SPEC §12) keeps its checkpoint and its frames up to step
  // `resumed_frames_to` (−1: none).
  void begin(Json header, std::optional<int> resumed_frames_to = std::nullopt);
  // Writes output `name` through writer(path); an OutputError is recorded, not
  // thrown. False if it failed.
  bool write(const std::string& name, const std::function<void(const std::string& path)>& writer);
  // Writes the final summary.json; after a failed write its status is "failed", with
  // the reason under "failure" (the solve's own status kept as "solve_status").
  // Throws OutputError if summary.json itself cannot be written. Returns what it wrote.
  Json finish(Json summary);

  bool failed() const { return !errors_.empty(); }
  std::string failure() const;  // the failed writes, "; "-separated
  std::string path(const std::string& name) const;
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::vector<std::string> errors_;
};

// case.toml: the resolved case, every key, that reruns this run (io/case.hpp to_toml).
void write_case_toml(RunOutputs& out, const Case& c);

}  // namespace fsi
