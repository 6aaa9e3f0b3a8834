// The quantities of interest a refinement study follows, read from a run's
// summary.json (NaN where the run has none: no contact, no fluid).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

struct Quantity {
  std::string name;  // summary.json key under "quantities"
  std::string unit;
  std::function<double(const Json& run_summary)> read;
};

// With a structure: max_displacement, tip_displacement (|u| at (L, H/2)), the
// contact's extent, centroid and force, and u_x, u_y at each output.probes point
// (probe_<k>_u_x, ...); with a fluid too: fluid_velocity_l2_in_structure and the
// structure's force and load. With a fluid: the fluid's force on each obstacle
// (obstacle_<i>_force_x, _y: SPEC §10's drag and lift) and, with a structure, on the
// obstacles and the structure together (fluid_force_x, _y: a benchmark's "drag and
// lift" of a body with a flag); at each output.fluid_probes point p, v_x, v_y
// (fluid_probe_<k>_p, ...) and, with two or more, the first's pressure less the
// second's (fluid_probe_pressure_difference: the DFG benchmark's Δp).
std::vector<Quantity> quantities(const Case& c);

}  // namespace fsi
