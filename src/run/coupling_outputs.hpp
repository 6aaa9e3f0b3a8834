// What both coupled runs (fluid.method "penalised" and "body-fitted") measure and
// write of their fixed-point loop: history.csv, the status and the stop.
#pragma once

#include <string>
#include <vector>

#include "coupling/fixed_point.hpp"
#include "io/case.hpp"
#include "run/run_measures.hpp"

namespace fsi {

// One line per pass. `body_fitted` adds the pass's fluid mesh (fluid_triangles,
// remeshed, t_mesh_s): the body-fitted method remeshes D \ φ(Ω_S0) every pass. Then
// u_x_i,u_y_i: ũ at each output.probes point, the records' `probes`.
void write_history(const std::string& path, const std::vector<IterationRecord>& history,
                   bool body_fitted);

// "failed" | "interrupted" | "converged" | "iteration limit" (summary.json's status).
const char* status_of(const CouplingResult& r);
// SPEC §8: 1 failed, 128 + signal interrupted, 0 converged, 3 iteration limit.
int exit_status_of(const CouplingResult& r);
// The measures of the loop's result r (its failure final: set any found after the
// loop first): status, stop (unless fluid_only: no loop ran), the displacement of ũ.
RunMeasures coupled_measures(const Case& c, const CouplingResult& r, bool fluid_only);

}  // namespace fsi
