// Where fluid.h_near refines the mesh of D (FluidParams::h_near, SPEC §10): the user's
// box fluid.band = [x_min, y_min, x_max, y_max], or the bounding box of the structure
// at rest and at its load-alone contact solution, grown by the width fluid.band.
//
// A box, not a distance band around the two shapes: the fixed point's iterates and
// the coupled answer lie between the structure at rest and where its loads push it,
// so the region swept between the two must be fine too, not only their outlines.
#pragma once

#include <array>
#include <optional>

#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

// Whether the band needs the load-alone contact solution (h_near > 0 and no box).
bool band_needs_structure(const Case& c);

// The band's box, clipped to D's box; nullopt without h_near. `s` is read only when
// band_needs_structure(c): its load-alone solution (StructureSetup::load_alone, the QP
// of eq. 17 with the structure's own loads f_S, h_N). Throws SolverFailure if that QP
// fails.
std::optional<std::array<double, 4>> fluid_band_box(const Case& c, StructureSetup* s);

// Whether `deformed` (the structure's final configuration) lies inside the band, with
// a margin of h_near: if not, part of it moved through coarse triangles, and
// summary.json says so (mesh.fluid.band_warning).
bool inside_band(const Mesh& deformed, const std::array<double, 4>& band, double margin);

}  // namespace fsi
