// structure.vtu and structure.png of a contact state.
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"
#include "io/figure.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// Point data: displacement, contact_multiplier, contact_status; cell data: von_mises.
// `deformed`: write deformed coordinates (to overlay the fluid) instead of the
// reference ones (to use ParaView's "Warp By Vector").
void write_structure_vtu(const std::string& path, const Case& c, const StructureSetup& s,
                         const ContactSolution& solution, bool deformed);

// Every obstacle of the case as a polygon: [obstacle]'s disk, or those of
// [[obstacles]] (half-planes clipped to `box`).
std::vector<std::vector<Point>> obstacle_outlines(const Case& c, const WorldBox& box);

// The deformed structure coloured by |u| over the undeformed outline, the obstacle,
// the contact zone in red, and a colour bar (the paper's Figs. 5–7).
// `title` (empty: the default) names a time run's frame.
void write_structure_png(const std::string& path, const Case& c, const StructureSetup& s,
                         const ContactSolution& solution, const std::string& title = "");

}  // namespace fsi
