// Where the structure is likely to go, told to the fluid before a coupled run (its
// substructured solve's first near region covers it: PenalisedStokes::expect_chi).
#pragma once

#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// The structure under its applied loads alone (with contact) moves as it will with
// the fluid's force added, in the paper's cases: its load-alone solution
// (StructureSetup::load_alone, shared with fluid.band's box), whose χ is the hint. A
// poor guess costs only a larger region or a second one; a failed QP (QpError) gives
// no hint, and pass 1's QP will say why. Other exceptions (bugs) propagate.
void expect_structure_under_loads(StructureSetup& s, FluidSetup& f);

}  // namespace fsi
