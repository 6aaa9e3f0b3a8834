// Colours of the figures: RGB in [0, 1], and the viridis map that shades every field
// (figure.hpp's Cairo canvas and raster.hpp's pixel painter both use it).
#pragma once

#include <array>

namespace fsi {

using Rgb = std::array<double, 3>;

// Viridis colour map, t in [0,1] (clamped; not finite: 0).
Rgb viridis(double t);

}  // namespace fsi
