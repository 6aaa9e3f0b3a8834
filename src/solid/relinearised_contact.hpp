// The contact problem with the gap by signed distance (SPEC §9, contact.gap =
// "normal"): the QP of eqs. (20)–(22) with the constraint linearised about u_k
// (solid/normal_contact.hpp), re-linearised about each solution until the
// linearisation has settled and the exact gap holds at every candidate vertex:
//     max_i |u_{k+1} − u_k|(X_i) ≤ 1e-10 · diam(Ω_S0)  and  min_i d(X_i + u) ≥ −1e-10 · diam(Ω_S0).
// Feasibility alone is not enough to stop: about a convex obstacle each linearised
// constraint is a tangent half-plane, stricter than the obstacle itself, so the first
// solution is feasible but held off along the tangent; the passes let it slide.
// Measured: 6–12 QPs on §7.1 (disk), 8 on a beam over two disks, 2 on a half-plane.
// Polygons: where a vertex's nearest feature is a sharp corner the normal turns with
// the position and the passes cycle; a polygon is therefore grown by a margin that
// rounds its corners (solid/signed_distance.hpp): 3 passes on a block's corner and a
// wedge's tip.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "solid/contact_solver.hpp"
#include "solid/normal_contact.hpp"

namespace fsi {

struct RelinearisedContact {
  ContactSolution solution;  // its `newton`: the steps of all linearisations, their residuals in turn
  int linearisations = 0;  // QPs solved
  double min_gap = 0;      // min d(X + u) over the candidates (m)
  double last_change = 0;  // max nodal |u_{k+1} − u_k| of the last pass (m)
};

struct RelinearisationOptions {
  int max_linearisations = 50;
  double relative_tolerance = 1e-10;  // of diam(Ω_S0), for both tests
};

// Starts from u_start (the structure at rest if empty). Throws SolverFailure if the
// tests are not met within max_linearisations, QpError if a QP fails.
RelinearisedContact solve_relinearised(ElasticContactSolver& solver, const CandidateSet& candidates,
                                       const std::vector<const Obstacle*>& obstacles, const Eigen::VectorXd& b_S,
                                       const Eigen::VectorXd& u_start, const RelinearisationOptions& options = {});

// The bounding box diagonal of the reference mesh: diam(Ω_S0) for the tolerances.
double diameter(const Mesh& mesh);

}  // namespace fsi
