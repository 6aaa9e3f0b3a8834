// What a run measured, typed: each runner fills it (its "measure" step), writes the
// headline keys of summary.json from it (add_measures) and returns it in RunResult,
// where the sweep's table reads it (never summary.json back by key).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "common/timer.hpp"
#include "mesh/mesh.hpp"
#include "run/outputs/summary.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

struct RunMeasures {
  MeshStatistics structure_mesh, fluid_mesh;  // 0 triangles: none (or not meshed yet)
  bool converged = false;
  std::string status = "failed";               // summary.json's "status"
  std::string failure, convergence_warning;    // empty: none
  int iterations = 0;                          // fixed-point passes; QP iterations for a contact problem
  // A coupled run's stop (SPEC §5): the paper's k (§6), ‖ũ − u^k‖ and ‖ũ‖ in L²(Ω_S0).
  struct Stop {
    int paper_k = 0;
    double final_increment = NAN, final_norm = NAN;
  };
  std::optional<Stop> stop;
  // ‖v_h‖_{L²} over the deformed structure, over it divided by ε, and over χ = 1
  // (the penalised method only).
  struct FluidInStructure {
    double v = NAN, v_over_eps = NAN, v_on_chi = NAN;
  };
  std::optional<FluidInStructure> fluid_in_structure;
  // max |u| and min u2 (a structure only).
  struct Displacement {
    double max = NAN, min_y = NAN;
  };
  std::optional<Displacement> displacement;
  std::optional<ContactSummary> contact;  // a run with contact
  double fluid_s = NAN;                   // the fluid phase's wall time (once written)
};

// summary.json's keys of m, in this order: converged, status, failure and
// convergence_warning (if any), iterations, paper_k, final_increment_l2,
// final_norm_l2, fluid_velocity_l2_in_structure(_over_eps), fluid_velocity_l2_on_chi,
// max_displacement, min_displacement_y (those m holds). "mesh" and "contact" are the
// runner's (it adds keys of its own to them).
void add_measures(Json& j, const RunMeasures& m);
// The run's last step before summary.json is final: its "timing_s" (all phases, the
// total so far) and m.fluid_s.
void finish_timing(Json& summary, RunMeasures& m, const PhaseTimes& times, const Stopwatch& total);

}  // namespace fsi
