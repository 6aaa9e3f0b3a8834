// The coupled map H of SPEC §5, u^k ↦ ũ^{k+1}: one fluid step on the structure's state
// u^k, its load on the structure, and the contact QP. The penalised fictitious domain
// (PenalisedMap) and the body-fitted fluid (BodyFittedMap) are two; FixedPointLoop
// iterates any of them, and a time loop can later own the windows (Relaxation::end_window).
#pragma once

#include <Eigen/Core>
#include <string>

#include "coupling/coupling_result.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

// What one evaluation of H gives besides ũ.
struct MapValue {
  ContactSolution structure;   // ũ^{k+1} (finite)
  Eigen::VectorXd fluid_load;  // eq. (33)'s fluid terms (or the body-fitted load) that gave it
  Eigen::VectorXd load;        // the whole b_S that gave it (empty: the map keeps none)
};

class CoupledMap {
 public:
  virtual ~CoupledMap() = default;
  // H(u) in pass k (1, 2, ...), the QP warm-started from `warm` (null: cold); the phase
  // times and counts go into `rec`. Throws SolverFailure naming the phase and pass.
  virtual MapValue operator()(const Eigen::VectorXd& u, int k, const ContactSolution* warm, IterationRecord& rec) = 0;
  // The progress line's part for the pass's phases ("active 3  chi 120  fluid ...").
  virtual std::string describe(const IterationRecord& rec) const = 0;
  virtual ElasticContactSolver& structure() = 0;
};

}  // namespace fsi
