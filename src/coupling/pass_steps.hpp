// Two steps of FixedPointLoop (fixed_point_loop.hpp): the first iterate, and the
// relaxation after a pass that did not converge.
#pragma once

#include <Eigen/Core>

#include "coupling/coupling_result.hpp"
#include "coupling/relaxation.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

// u⁰: the structure at rest, or `initial` (a restart's) projected onto the feasible
// set, so that the first pass starts from a state the QP allows. Throws
// std::invalid_argument if `initial` does not fit the mesh or is not finite (a bug of
// the caller, not a failed solve).
Eigen::VectorXd initial_iterate(ElasticContactSolver& structure, const Eigen::VectorXd& initial);

// u^{k+1} = relaxation(u^k, ũ^{k+1}) after pass k, its ω recorded in `rec` and in the
// last history record; a SolverFailure naming the relaxation and the pass if it fails
// or gives a non-finite iterate.
// `project`: the structure step's projection onto the feasible set.
Eigen::VectorXd relaxed_iterate(Relaxation& relaxation, const Projection& project, const Eigen::VectorXd& u,
                                const Eigen::VectorXd& u_tilde, int k, IterationRecord& rec, CouplingResult& result);

}  // namespace fsi
