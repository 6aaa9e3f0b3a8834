#include "common/fault.hpp"

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "common/errors.hpp"

namespace fsi {

void fault_point(const char* phase) {
  const char* fault = std::getenv("FSICONTACT_FAULT");
  if (!fault) return;
  const std::size_t n = std::strlen(phase);
  if (std::strncmp(fault, phase, n) != 0 || (fault[n] != '\0' && fault[n] != ':')) return;
  if (std::strcmp(fault + n, ":oom") == 0) throw std::bad_alloc();
  throw SolverFailure(std::string("injected fault in the ") + phase + " phase (FSICONTACT_FAULT)");
}

void fault_step(int step) {
  const char* fault = std::getenv("FSICONTACT_FAULT");
  if (!fault || std::strncmp(fault, "sigterm@", 8) != 0) return;
  if (std::atoi(fault + 8) == step) std::raise(SIGTERM);
}

}  // namespace fsi
