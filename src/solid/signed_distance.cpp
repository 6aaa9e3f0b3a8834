#include "solid/signed_distance.hpp"

#include <cmath>

namespace fsi {

SignedDistance DiskObstacle::at(const Point& x) const {
  const Point v = x - c_;
  const double rho = v.norm();
  SignedDistance s;
  s.d = rho - r_;
  s.n = rho > 0 ? Point(v / rho) : Point(0, 1);
  return s;
}

NearestObstacle nearest(const std::vector<const Obstacle*>& obstacles, const Point& x) {
  NearestObstacle out;
  out.gap.d = INFINITY;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const SignedDistance s = obstacles[i]->at(x);
    if (s.d < out.gap.d) out.gap = s, out.index = static_cast<int>(i);
  }
  return out;
}

}  // namespace fsi
