// What both coupled runs (fluid.method "penalised" and "body-fitted") measure and
// write of their fixed-point loop: history.csv, the status and the stop.
#pragma once

#include <string>
#include <vector>

#include "coupling/fixed_point.hpp"
#include "io/case.hpp"
#include "fem/probes.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/outputs/run_measures.hpp"
#include "run/structure_setup.hpp"

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
// loop first): status, iterations, the displacement of ũ.
RunMeasures coupled_measures(const Case& c, const CouplingResult& r);
// Fills each pass's record with ũ at output.probes (history.csv's u_x_i, u_y_i);
// none without probes.
PassObserver probe_observer(const ProbeSet& probes);

// The stop of a loop that ran (SPEC §5; the paper's k = iterations − 1).
RunMeasures::Stop coupled_stop(const CouplingResult& r);

// summary.json's tip_displacement, displacement_at, structure_force (the fluid's
// load's resultant) and structure_load (the same off Γ_D) of the final state.
void add_structure_displacements(Json& j, const Case& c, const StructureSetup& s, const CouplingResult& r);
// The coupled structure's keys (SPEC §8, §9, §11): contact (with its gap), kkt,
// newton (a nonlinear model's last pass) and relaxation.
void add_coupled_structure(Json& j, const Case& c, const StructureSetup& s, const CouplingResult& r,
                           const RunMeasures& m);
// The coupled structure's files: structure.vtu and fsi.pvd (when the fluid is written:
// `fluid_vtu_written`; never a .pvd that names a missing file), structure.png (beside a
// fluid picture: `have_fluid`), and history.csv (write_history).
void write_coupled_files(RunOutputs& out, const Case& c, const StructureSetup& s, const CouplingResult& r,
                         bool have_fluid, bool fluid_vtu_written, bool body_fitted, bool passes_history = true);

}  // namespace fsi
