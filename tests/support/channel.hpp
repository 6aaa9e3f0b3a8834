// The channel of the hole-force tests: Stokes flow (μ = 0.0035, Vmax = 1) through
// (0, 2) × (−0.5, 0.5), inflow on the left, outflow on the right, walls top and bottom.
#pragma once

#include "io/case.hpp"

namespace fsi::testing {

inline FluidParams channel(double mu) {
  FluidParams f;
  f.L1 = 2.0, f.H1 = 0.5, f.H2 = 0.5;
  f.mu = mu, f.Vmax = 1.0, f.f = Point::Zero();
  f.sides = {"inflow", "wall", "outflow", "wall"};
  return f;
}

}  // namespace fsi::testing
