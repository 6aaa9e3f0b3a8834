// The fluid alone marched in time on its fixed mesh (structure.shape = "none", SPEC
// §12), whichever element (fluid.element): what the time run (time_fluid_problem.cpp)
// asks of it — start, step, the state to write, the forces on the holes, the
// checkpoint's part. The mini element's march is FluidTimeStepper on PenalisedStokes,
// the Taylor–Hood one's TaylorHoodFlow; the run's loop, outputs and checkpoints are
// the same for both.
#pragma once

#include <memory>
#include <vector>

#include "fluid/fluid_time_stepper.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

class FluidMarch {
 public:
  virtual ~FluidMarch() = default;
  virtual const Mesh& mesh() const = 0;
  // From rest, or (`steady`) from the steady flow for the data at t = 0: SolverFailure
  // "the steady flow at t = 0 ...". After restore(), from the checkpoint's state.
  virtual void start(bool steady) = 0;
  // One step to time() + Δt with the data there. SolverFailure: the state stays at t.
  virtual void step() = 0;
  // The state at the vertices (the mini element's bubbles too): what the frames show.
  virtual const FluidSolution& state() const = 0;
  virtual double time() const = 0;
  virtual int steps() const = 0;
  // Newton's (and Picard's) steps in the last step; 0 for Stokes.
  virtual int newton_steps() const = 0;
  virtual bool navier_stokes() const = 0;
  // The fluid's force on each hole of the case (obstacle_hole_names) at the state,
  // with the last step's ρ∂v/∂t and the data at its time (SPEC §10 residual method).
  virtual std::vector<Point> forces() = 0;
  // summary.json's "fluid_at" at the state (output.fluid_probes).
  virtual Json probes() const = 0;
  // summary.json's "fluid".
  virtual Json json() const = 0;
  // The state's part of a checkpoint, and the state from one (before start()).
  virtual void save(Checkpoint& k) const = 0;
  virtual void restore(const Checkpoint& k) = 0;
};

// The case's element's march on `mesh` (FluidSetup or TaylorHoodSetup).
std::unique_ptr<FluidMarch> make_fluid_march(const Case& c, Mesh mesh);

}  // namespace fsi
