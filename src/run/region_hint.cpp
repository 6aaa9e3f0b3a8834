#include "run/region_hint.hpp"

#include "qp/qp_problem.hpp"

namespace fsi {

void expect_structure_under_loads(StructureSetup& s, FluidSetup& f) {
  const Mesh& reference = s.mesh();
  const int nv = reference.num_vertices();
  try {
    const ContactSolution& guess = s.load_alone();
    if (guess.u.allFinite()) f.stokes->expect_chi((*f.chi)(displaced(reference, guess.u.head(nv), guess.u.tail(nv))));
  } catch (const QpError&) {  // no hint: the region grows when needed
  }
}

}  // namespace fsi
