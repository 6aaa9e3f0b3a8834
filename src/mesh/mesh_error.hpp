// The one exception of the mesh layer: a mesh that cannot be made or read, with
// the reason. Callers add the file and the case key.
#pragma once

#include <stdexcept>

namespace fsi {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fsi
