#include "mesh/mesh_geometry.hpp"

#include <cmath>

namespace fsi {

double reference_length(double extent) {
  if (!std::isfinite(extent) || !(extent > 0) || (extent >= 0x1p-8 && extent <= 0x1p8)) return 1;
  int exponent = 0;
  std::frexp(extent, &exponent);
  return std::ldexp(1.0, exponent);
}

}  // namespace fsi
