// The quantities of interest a refinement study follows, read from a run's
// summary.json (NaN where the run has none: no contact, no fluid).
#pragma once

#include <string>
#include <vector>

#include "run/outputs/summary.hpp"

namespace fsi {

struct Quantity {
  std::string name;  // summary.json key under "quantities"
  std::string unit;
  double (*read)(const Json& run_summary);
};

// max_displacement, tip_displacement (|u| at (L, H/2)), contact_x_min, contact_x_max;
// with a fluid also fluid_velocity_l2_in_structure, structure_force_x, structure_force_y.
const std::vector<Quantity>& quantities(bool with_fluid);

}  // namespace fsi
