// A time run's state at the end of one step, to continue from (SPEC §12:
// time.checkpoint_every, `fsicontact run CASE --resume DIR`). Named arrays of doubles
// (integers and flags stored as doubles: exact below 2^53), written in binary so that
// a resumed run starts from the very bits the interrupted one had, and atomically
// (io/atomic_file.hpp): a checkpoint is whole or absent, never half-written.
//
// The file: a text header ("fsicontact checkpoint 1", the run's kind, its case's
// fingerprint, the step and its time, one line "name count" per array), a line "data",
// then the arrays' doubles in their order (the machine's little-endian bytes) and a
// 64-bit FNV-1a checksum of them. Anything else (another file, a truncated or altered
// checkpoint) is refused as an InputError naming the file and what is wrong with it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fsi {

class Checkpoint {
 public:
  std::string kind;         // the Problem's kind ("contact", "fluid", "fsi")
  std::string fingerprint;  // of the case it continues (checkpoint_fingerprint)
  int step = 0;
  double t = 0;

  void put(const std::string& name, const Eigen::VectorXd& values);
  void put(const std::string& name, double value) { put(name, Eigen::VectorXd(Eigen::VectorXd::Constant(1, value))); }
  void put_matrix(const std::string& name, const Eigen::MatrixXd& values);  // its shape kept: name.rows, name.cols
  void put_ints(const std::string& name, const std::vector<int>& values);

  bool has(const std::string& name) const { return arrays_.count(name) != 0; }
  // The array `name`; InputError (the checkpoint's file and the name) if it is absent
  // or, with `size` ≥ 0, of another length.
  const Eigen::VectorXd& vector(const std::string& name, long size = -1) const;
  double scalar(const std::string& name) const { return vector(name, 1)[0]; }
  int integer(const std::string& name) const;
  Eigen::MatrixXd matrix(const std::string& name) const;
  std::vector<int> ints(const std::string& name) const;

  std::string source;  // the file read (for messages); empty when built in memory
  const std::map<std::string, Eigen::VectorXd>& arrays() const { return arrays_; }
  std::vector<std::string> order;  // the arrays' names in the order they were put

 private:
  std::map<std::string, Eigen::VectorXd> arrays_;
};

// The file name inside a run's directory.
inline const char* checkpoint_file_name() { return "checkpoint.bin"; }

// Writes `c` to `path` atomically (OutputError on failure: path and reason).
void write_checkpoint(const std::string& path, const Checkpoint& c);
// Reads `path`; InputError ("<path>: not a checkpoint of fsicontact: ...", exit 2) if it
// is missing, not a checkpoint, truncated or altered.
Checkpoint read_checkpoint(const std::string& path);

// 64-bit FNV-1a of `bytes`, as 16 hex digits: the fingerprint of a case's text.
std::string fnv1a_hex(const std::string& bytes);

}  // namespace fsi
