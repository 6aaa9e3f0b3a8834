#include "io/colour.hpp"

#include <algorithm>
#include <cmath>

namespace fsi {

Rgb viridis(double t) {
  static const double anchors[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                       {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                       {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  const double s = t * 8;
  const int k = std::min(7, static_cast<int>(s));
  const double w = s - k;
  Rgb c;
  for (int i = 0; i < 3; ++i) c[i] = ((1 - w) * anchors[k][i] + w * anchors[k + 1][i]) / 255.0;
  return c;
}

}  // namespace fsi
