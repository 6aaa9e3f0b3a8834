#include "run/fluid_structure_problem.hpp"

#include "run/outputs/coupling_outputs.hpp"

namespace fsi {

void FluidStructureProblem::measure_final_state(RunResult& r, const MeshStatistics& fluid_mesh) {
  if (!result_.failure.empty()) result_.converged = false;
  RunMeasures& m = r.measures = coupled_measures(c_, result_);
  m.structure_mesh = s_stats_, m.fluid_mesh = fluid_mesh;
  measure_structure(m);
  r.displacement = result_.structure.u;
  r.exit_status = exit_status_of(result_);
  if (!result_.failure.empty())
    r.failure = result_.failure + " (the last good state is written in " + c_.output.dir + "/)";
}

void FluidStructureProblem::measure_coupled_structure(RunMeasures& m) const {
  m.stop = coupled_stop(result_);
  m.contact = summarize_contact(*s_->solver, result_.structure);
}

void FluidStructureProblem::summarise_coupled_structure(Json& j, const RunMeasures& m) const {
  add_coupled_structure(j, c_, *s_, result_, m);
}

std::string FluidStructureProblem::passes_note() const {
  return std::to_string(result_.iterations) + " iterations" + (result_.converged ? "" : " (not converged)");
}

}  // namespace fsi
