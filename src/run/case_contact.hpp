// The case's contact as the structure's solver takes it (solid/contact_gap.hpp).
#pragma once

#include "io/case.hpp"
#include "solid/contact_gap.hpp"

namespace fsi {

// contact.gap's rule with the case's obstacles ([obstacle]'s disk, or [[obstacles]],
// polygons held off by kPolygonMargin · diam) and contact.boundary's candidates.
ContactGap case_contact_gap(const Case& c, const Mesh& mesh);

}  // namespace fsi
