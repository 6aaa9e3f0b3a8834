// structure.vtu and structure.png of a contact state.
#pragma once

#include <string>

#include "io/case.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// Point data: displacement, contact_multiplier, contact_status; cell data: von_mises.
// `deformed`: write deformed coordinates (to overlay the fluid) instead of the
// reference ones (to use ParaView's "Warp By Vector").
void write_structure_vtu(const std::string& path, const StructureSetup& s,
                         const ContactSolution& solution, bool deformed);

// The deformed structure coloured by |u| over the undeformed outline, the obstacle,
// the contact zone in red, and a colour bar (the paper's Figs. 5–7).
void write_structure_png(const std::string& path, const Case& c, const StructureSetup& s,
                         const ContactSolution& solution);

}  // namespace fsi
