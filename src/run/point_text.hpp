// A point in the messages of the mesh checks (mesh_checks.cpp, hole_checks.cpp).
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace fsi {

// "(x, y)" in the shortest digits that read back as the same doubles.
std::string point_text(const Point& p);

}  // namespace fsi
