#include "fluid/mumps_handle.hpp"

#include <algorithm>
#include <utility>

#include "common/errors.hpp"

namespace fsi {

MumpsHandle::MumpsHandle(std::string who) : who_(std::move(who)) {
  id_.comm_fortran = -987654;  // MPI_COMM_WORLD of the sequential stub library
  id_.par = 1;
  id_.sym = 2;
  call(-1, "initialisation");
  initialised_ = true;
  icntl(1) = icntl(2) = icntl(3) = -1;  // no output
  icntl(4) = 0;
  icntl(28) = 1;  // sequential analysis
}

MumpsHandle::~MumpsHandle() {
  if (initialised_) {
    id_.job = -2;
    dmumps_c(&id_);
  }
}

void MumpsHandle::call(int job, const char* phase) {
  id_.job = job;
  dmumps_c(&id_);
  check(phase);
}

void MumpsHandle::check(const char* phase) const {
  if (id_.info[0] < 0)
    throw SolverFailure(who_ + phase + " failed, INFO(1) = " + std::to_string(id_.info[0]) +
                        ", INFO(2) = " + std::to_string(id_.info[1]));
}

int MumpsHandle::factorize_numeric() {
  for (int attempt = 0;; ++attempt) {
    id_.job = 2;
    dmumps_c(&id_);
    const int status = id_.info[0];
    const bool workspace = status == -8 || status == -9 || status == -14 || status == -15 ||
                           status == -17 || status == -20;
    if (!workspace || attempt == 4) return status;
    icntl(14) = std::max(2 * icntl(14), 40);
  }
}

}  // namespace fsi
