// The coupled map H of SPEC §5, u^k ↦ ũ^{k+1} = structure step ∘ fluid step:
//   the fluid's load on the structure at its state u^k (FluidStep: the penalised
//   fictitious domain, coupling/penalised_step.hpp, or the body-fitted fluid,
//   coupling/body_fitted_step.hpp), then the contact QP for b_S = b_applied + that
//   load (StructureStep, solid/structure_step.hpp).
// FixedPointLoop (fixed_point_loop.hpp) iterates any CoupledMap and does not know which
// fluid, gap or material it holds; a time loop will own the windows
// (FixedPointCoupling::next_window) and give the fluid step the time level's data.
#pragma once

#include <Eigen/Core>
#include <string>

#include "coupling/coupling_result.hpp"
#include "solid/contact_solver.hpp"
#include "solid/structure_step.hpp"

namespace fsi {

// What one evaluation of H gives besides ũ.
struct MapValue {
  ContactSolution structure;   // ũ^{k+1} (finite)
  Eigen::VectorXd fluid_load;  // eq. (33)'s fluid terms (or the body-fitted load) that gave it
  Eigen::VectorXd load;        // the whole b_S that gave it (empty: the map keeps none)
};

// One pass's inputs besides u^k.
struct Pass {
  int k = 1;                               // 1, 2, ...
  const ContactSolution* warm = nullptr;   // the QP's warm start (null: cold)
  double newton_step_tol = 0;              // StructureStep::solve's (inexact Newton)
};

class CoupledMap {
 public:
  virtual ~CoupledMap() = default;
  // H(u) in pass `pass.k`; the phase times and counts go into `rec`. Throws
  // SolverFailure naming the phase and pass.
  virtual MapValue operator()(const Eigen::VectorXd& u, const Pass& pass, IterationRecord& rec) = 0;
  // The progress line's part for the pass's phases ("active 3  chi 120  fluid ...").
  virtual std::string describe(const IterationRecord& rec) const = 0;
  virtual StructureStep& structure() = 0;
};

// The fluid's half of a pass (SPEC §5 steps 2–3).
class FluidStep {
 public:
  virtual ~FluidStep() = default;
  // The fluid's load on the structure (2nv) at its state u in pass k, its phases timed
  // in `rec`. Throws SolverFailure naming the phase and the pass.
  virtual Eigen::VectorXd load(const Eigen::VectorXd& u, int k, IterationRecord& rec) = 0;
  // The structure's answer to the last load (finite): the body-fitted fluid refuses a
  // structure in contact (SolverFailure) and keeps its pass as the last good one.
  virtual void accept(const ContactSolution&, int) {}
  virtual std::string describe(const IterationRecord& rec) const = 0;
};

// H = structure step ∘ fluid step.
class ComposedMap final : public CoupledMap {
 public:
  ComposedMap(FluidStep& fluid, StructureStep& structure, const Eigen::VectorXd& b_applied)
      : fluid_(fluid), structure_(structure), b_applied_(b_applied) {}

  MapValue operator()(const Eigen::VectorXd& u, const Pass& pass, IterationRecord& rec) override;
  std::string describe(const IterationRecord& rec) const override { return fluid_.describe(rec); }
  StructureStep& structure() override { return structure_; }

 private:
  FluidStep& fluid_;
  StructureStep& structure_;
  const Eigen::VectorXd& b_applied_;  // f_S and h_N part of b_S (eq. 16)
};

}  // namespace fsi
