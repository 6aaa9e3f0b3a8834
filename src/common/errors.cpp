#include "common/errors.hpp"

#include <cstring>

namespace fsi {

OutputError::OutputError(const std::string& path, int err)
    : std::runtime_error("cannot write " + path + ": " + std::strerror(err)) {}

}  // namespace fsi
