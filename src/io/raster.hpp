// A P1 field painted straight into an image's pixels: each pixel whose centre lies in
// a triangle takes the colour of the value interpolated there. Cairo's mesh patterns
// (a Gouraud patch per triangle) took 0.1–0.2 s for the §7.2 box at hF = 0.01 and
// most of a fine run's figure time (measured, docs/performance.md "Outputs"); this
// visits each pixel once.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// 32-bit pixels 0x00RRGGBB (Cairo's RGB24), `stride` bytes a row; only the pixels of
// the rectangle `clip` = [x0, y0, x1, y1) are written.
struct PixelImage {
  std::uint32_t* data;
  int stride;
  std::array<int, 4> clip;
};

// `at`: the vertices in pixel coordinates (x right, y down); `t01`: the field per
// vertex scaled to [0, 1] (clamped), coloured by viridis.
void paint_field(const PixelImage& image, const std::vector<Point>& at,
                 const std::vector<std::array<int, 3>>& triangles, const std::vector<double>& t01);

}  // namespace fsi
