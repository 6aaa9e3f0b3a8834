// What both coupled runs (fluid.method "penalised" and "body-fitted") write of their
// fixed-point loop: history.csv and the status word of summary.json.
#pragma once

#include <string>
#include <vector>

#include "coupling/fixed_point.hpp"

namespace fsi {

// One line per pass. `body_fitted` adds the pass's fluid mesh (fluid_triangles,
// remeshed, t_mesh_s): the body-fitted method remeshes D \ φ(Ω_S0) every pass.
void write_history(const std::string& path, const std::vector<IterationRecord>& history,
                   bool body_fitted);

// "failed" | "interrupted" | "converged" | "iteration limit" (summary.json's status).
const char* status_of(const CouplingResult& r);

}  // namespace fsi
