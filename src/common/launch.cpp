#include "common/launch.hpp"

#include <algorithm>
#include <cstdlib>

namespace fsi {
namespace {

// The first of the launchers' variables that is set, or `otherwise`.
int first_set(const char* const (&variables)[3], int otherwise) {
  for (const char* variable : variables)
    if (const char* v = std::getenv(variable)) return std::atoi(v);
  return otherwise;
}

}  // namespace

int launched_ranks() { return std::max(1, first_set({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}, 1)); }

int launched_rank() {
  return std::clamp(first_set({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}, 0), 0, launched_ranks() - 1);
}

}  // namespace fsi
