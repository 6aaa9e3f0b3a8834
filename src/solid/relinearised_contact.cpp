#include "solid/relinearised_contact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace fsi {
namespace {

// max over vertices of |a − b| at the vertex (both components): the change of the
// deformed position, the length the tolerance is stated in.
double max_nodal_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int nv) {
  double m = 0;
  for (int v = 0; v < nv; ++v) m = std::max(m, std::hypot(a[v] - b[v], a[nv + v] - b[nv + v]));
  return m;
}

}  // namespace

double diameter(const Mesh& mesh) {
  Point lo = Point::Constant(INFINITY), hi = Point::Constant(-INFINITY);
  for (const Point& p : mesh.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

RelinearisedContact solve_relinearised(ElasticContactSolver& solver, const CandidateSet& candidates,
                                       const std::vector<const Obstacle*>& obstacles, const Eigen::VectorXd& b_S,
                                       const Eigen::VectorXd& u_start, const RelinearisationOptions& options) {
  const Mesh& mesh = solver.mesh();
  const int nv = mesh.num_vertices();
  const double tol = options.relative_tolerance * diameter(mesh);
  Eigen::VectorXd u_k = u_start.size() ? u_start : Eigen::VectorXd::Zero(2 * nv);
  RelinearisedContact r;
  const ContactSolution* warm = nullptr;
  NewtonReport newton;  // over all linearisations: each one's Newton steps count
  for (int k = 1; k <= options.max_linearisations; ++k) {
    solver.set_constraint(assemble_normal_contact(mesh, candidates, obstacles, u_k));
    r.solution = solver.solve(b_S, warm);
    newton.steps += r.solution.newton.steps;
    newton.cuts += r.solution.newton.cuts;
    newton.load_steps = std::max(newton.load_steps, r.solution.newton.load_steps);
    newton.residual = r.solution.newton.residual;
    newton.history.insert(newton.history.end(), r.solution.newton.history.begin(), r.solution.newton.history.end());
    r.solution.newton = newton;
    if (!r.solution.u.allFinite()) throw SolverFailure("contact.gap = \"normal\": the QP returned a non-finite displacement");
    r.linearisations = k;
    r.min_gap = min_exact_gap(mesh, candidates, obstacles, r.solution.u);
    r.last_change = max_nodal_change(r.solution.u, u_k, nv);
    if (r.last_change <= tol && r.min_gap >= -tol) return r;
    u_k = r.solution.u;
    warm = &r.solution;
  }
  throw SolverFailure("contact.gap = \"normal\": the linearisation did not settle in " +
                      std::to_string(options.max_linearisations) + " passes (last change " + approx(r.last_change, 3) +
                      " m, min gap " + approx(r.min_gap, 3) + " m, tolerance " + approx(tol, 3) + " m)");
}

}  // namespace fsi
