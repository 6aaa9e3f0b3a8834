// A structure's time history (SPEC §12): one row per step for history.csv, and what
// summary.json says of the whole run: the energy's balance and the contact intervals
// (when it touches, for how long, how hard, and how it leaves: the bar impact's
// duration 2L/c, plateau ρ c v0 and rebound −v0).
#pragma once

#include <string>
#include <vector>

#include "fem/probes.hpp"
#include "mesh/mesh.hpp"
#include "run/outputs/summary.hpp"
#include "run/structure_setup.hpp"
#include "solid/newmark.hpp"

namespace fsi {

struct StructureRow {
  int step = 0;
  double t = 0;
  int qp_iterations = 0;    // over the step's QPs (linearisations, Newton steps)
  int active_nodes = 0;
  double max_u = 0;
  double kinetic = 0, elastic = 0;
  double work = 0;          // of the applied load from t = 0 (trapezoidal in time)
  Point velocity = Point::Zero();       // of the centre of mass: momentum / mass
  Point contact_force = Point::Zero();  // Σ C_Sᵀα per component: the obstacles' push (N/m)
  // A coupled step (SPEC §12): the coupling's passes and the fluid's force on the
  // structure (the resultant of eq. (33)'s load, N/m); passes < 0: the structure alone.
  int passes = -1;
  Point fluid_force = Point::Zero();
  std::vector<Point> probes;            // output.probes' displacements
};

// The row of state `s`: energies by `newmark`'s mass and the solver's material, the
// contact force C_Sᵀα, the probes (null: none); `work` the applied loads' so far.
StructureRow structure_row(const NewmarkState& s, const Newmark& newmark, const StructureSetup& setup,
                           const ProbeSet* probes, double work, int qp_iterations);

// history.csv, atomically: step,t,qp_iterations,active_nodes,max_u,kinetic,elastic,
// work,energy_error,vx,vy,contact_fx,contact_fy[,passes,fluid_fx,fluid_fy][,probe_i_ux,
// probe_i_uy...] (passes and the fluid's force for a coupled run); energy_error =
// kinetic + elastic − work − (the same at t = 0), every number to its last digit.
void write_structure_history(const std::string& path, const StructureRow& initial, const std::vector<StructureRow>& rows);

// summary.json's "energy": initial and final total (kinetic + elastic − work), the
// largest |drift| over the run and its time, relative to the largest kinetic + elastic.
Json energy_json(const StructureRow& initial, const std::vector<StructureRow>& rows);

// summary.json's "contact_intervals": each maximal run of steps with an active node,
// from the first step in contact to the last: start, end (s), duration (end − start +
// dt: the steps' span), peak |contact force| and its time, and the centre of mass's
// velocity before (the step before start) and after (the step after end, null while
// still in contact at the end).
Json contact_intervals_json(const StructureRow& initial, const std::vector<StructureRow>& rows, double dt);

}  // namespace fsi
