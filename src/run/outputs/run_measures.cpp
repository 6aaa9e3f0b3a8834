#include "run/outputs/run_measures.hpp"

namespace fsi {

void add_measures(Json& j, const RunMeasures& m) {
  j["converged"] = m.converged;
  j["status"] = m.status;
  if (!m.failure.empty()) j["failure"] = m.failure;
  if (!m.convergence_warning.empty()) j["convergence_warning"] = m.convergence_warning;
  j["iterations"] = m.iterations;
  if (m.stop) {
    j["paper_k"] = m.stop->paper_k;  // the paper's counter k at the stop (§6)
    j["final_increment_l2"] = m.stop->final_increment;
    j["final_norm_l2"] = m.stop->final_norm;  // ‖ũ‖_{L²(Ω_S0)}: the scale tol is measured against
  }
  if (m.fluid_in_structure) {
    j["fluid_velocity_l2_in_structure"] = m.fluid_in_structure->v;
    j["fluid_velocity_l2_in_structure_over_eps"] = m.fluid_in_structure->v_over_eps;
    j["fluid_velocity_l2_on_chi"] = m.fluid_in_structure->v_on_chi;
  }
  if (m.displacement) {
    j["max_displacement"] = m.displacement->max;
    j["min_displacement_y"] = m.displacement->min_y;
  }
}

void finish_timing(Json& summary, RunMeasures& m, const PhaseTimes& times, const Stopwatch& total) {
  summary["timing_s"] = timing_json(times, total.elapsed());
  m.fluid_s = times.get("fluid");
}

}  // namespace fsi
