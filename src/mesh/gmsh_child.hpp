// Runs a piece of Gmsh work in a forked child process, so that nothing Gmsh does
// (an exception thrown inside its OpenMP regions, which std::terminate()s, a crash,
// a hang, a runaway allocation) can take our process down or stall it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fsi {

struct ChildLimits {
  double seconds = 600;          // wall-clock time before the child is killed
  std::size_t extra_memory = 0;  // address space it may add to the parent's (0: no cap)
};

// What the child does, in words for messages: "meshing the structure".
struct ChildTask {
  std::string doing;
  std::string out_of_memory_detail;  // appended to the out-of-memory message
};

// Forks; the child runs `job` and sends back the bytes it returns. Returns them, or
// throws MeshError if the child threw, crashed, exited early, or ran out of memory
// or time. The child is always reaped; it prints nothing to our terminal.
std::vector<char> run_in_child(const std::function<std::vector<char>()>& job, const ChildTask& task,
                               const ChildLimits& limits);

// Inside a child's job, before it runs what it was not written by us (a user's .geo
// script): from here on no file may grow beyond zero bytes and no process or thread be
// started (RLIMIT_FSIZE, RLIMIT_NPROC; the latter has no effect for root). A second
// fence behind geo_script.hpp's refusals.
void forbid_side_effects();

// Physical memory of this machine in bytes (0 if unknown).
std::size_t physical_memory();

}  // namespace fsi
