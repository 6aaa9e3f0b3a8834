// fluid.method = "penalised" (SPEC §3, §5): the fluid on a fixed mesh of D, the
// structure seen through χ and the penalty (1/ε)χ v. What its two kinds share (the
// set-up, the fluid's measures, summary keys and files); each kind says what it
// solves and what it adds of the structure (run/penalised_kinds.cpp).
#pragma once

#include <array>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "coupling/force_transfer.hpp"
#include "run/fluid_setup.hpp"
#include "run/fluid_structure_problem.hpp"

namespace fsi {

class PenalisedProblem : public FluidStructureProblem {
 public:
  using FluidStructureProblem::FluidStructureProblem;
  // The meshes, the structure, fluid.band's box (around the structure's load-alone
  // solution: after the structure) and the fluid, each timed as its phase.
  void set_up(PhaseTimes& times) override;
  // The final state's measures (ũ: the solution if converged, after a failure the last
  // good one); a converged run with a quantity it cannot state is a failure. Then the
  // velocity picture starts on a second core.
  void measure(RunResult& r) override;
  void summarise(RunResult& r) override;
  void write(RunOutputs& out) override;
  void final_fields(FinalFields& out) const override;

 protected:
  // The vertices drawn in red on the velocity picture (the contact zone).
  virtual std::vector<int> contact_vertices() const = 0;

  // eq. (33)'s fluid terms (or their pull-back) with the case's fluid and the fluid
  // solver's ε, on the structure's P1 mesh or its P2 space.
  FluidForce fluid_force() const;
  // After the solve: the last fluid solution everywhere when an output draws or writes
  // the whole fluid (null without them, or if completing it fails: result_.failure).
  void complete_fluid();

  std::future<void> fonts_;  // the figures' fonts, loaded while the run meshes and solves
  FluidSetup* f_ = nullptr;
  std::optional<std::array<double, 4>> band_;
  MeshStatistics f_stats_;
  const FluidSolution* fluid_ = nullptr;
  std::future<std::string> png_;
};

}  // namespace fsi
