#include "coupling/fixed_point.hpp"

#include <cmath>
#include <cstdio>

#include "common/timer.hpp"
#include "common/errors.hpp"

namespace fsi {

FixedPointCoupling::FixedPointCoupling(Parts parts, double tol, int max_iterations)
    : p_(parts), tol_(tol), max_iterations_(max_iterations),
      M_(assemble_vector_mass(parts.structure.mesh())) {
  p_.relaxation.project = [this](const Eigen::VectorXd& z) { return p_.structure.project(z); };
}

CouplingResult FixedPointCoupling::run() {
  const Mesh& reference = p_.structure.mesh();
  const int nv = reference.num_vertices();
  CouplingResult result;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * nv);  // u⁰ = 0: feasible at rest
  const ContactSolution* warm = nullptr;
  auto fail = [&](const std::string& phase, const std::string& what) {
    throw SolverFailure(phase + " failed at fixed-point iteration " +
                        std::to_string(result.iterations) + ": " + what);
  };

  for (int k = 1; k <= max_iterations_; ++k) {
    result.iterations = k;
    IterationRecord rec;
    rec.iteration = k;
    {
      const Stopwatch clock;  // step 2: χ of φ^k(Ω_S0)
      const Eigen::VectorXd chi = p_.chi(displaced(reference, u.head(nv), u.tail(nv)));
      p_.fluid.set_chi(chi);
      rec.chi_triangles = static_cast<int>((chi.array() > 0).count());
      rec.t_chi = clock.elapsed();
    }
    const FluidSolution* fluid = nullptr;
    {
      const Stopwatch clock;
      const int reused_before = p_.fluid.timing().reused;
      try {
        fluid = &p_.fluid.solve();
      } catch (const std::exception& e) {
        fail("the fluid solve", e.what());
      }
      rec.fluid_reused = p_.fluid.timing().reused > reused_before;
      rec.t_fluid = clock.elapsed();
    }
    Eigen::VectorXd b_S;
    {
      const Stopwatch clock;  // step 3: b_S from v∘φ^k, p∘φ^k (eq. 33)
      const FluidField field(p_.fluid_locator, *fluid);
      b_S = p_.b_applied + p_.force(sample_at_deformed_vertices(field, reference, u), u);
      if (!b_S.allFinite()) fail("the force transfer", "non-finite load on the structure");
      rec.t_transfer = clock.elapsed();
    }
    {
      const Stopwatch clock;  // step 4: the contact QP, warm-started
      try {
        result.structure = p_.structure.solve(b_S, warm);
      } catch (const std::exception& e) {
        fail("the contact QP", e.what());
      }
      if (!result.structure.u.allFinite()) fail("the contact QP", "non-finite displacement");
      rec.t_structure = clock.elapsed();
    }
    const Eigen::VectorXd d = result.structure.u - u;  // step 5
    rec.increment = std::sqrt(std::max(0.0, d.dot(M_ * d)));
    rec.active_nodes = result.structure.qp.active_count();
    result.final_increment = rec.increment;
    const bool converged = rec.increment < tol_;
    if (!converged && k < max_iterations_) {
      u = p_.relaxation.next(u, result.structure.u);
      rec.omega = p_.relaxation.omega();
    }
    result.history.push_back(rec);
    if (progress) {
      char omega[16] = "-";
      if (std::isfinite(rec.omega)) std::snprintf(omega, sizeof omega, "%.3g", rec.omega);
      char line[256];
      std::snprintf(line, sizeof line,
                    "[coupling] it %3d: increment %.4e  omega %-6s active %2d  chi %5d  "
                    "fluid %.3f s%s  structure %.4f s",
                    k, rec.increment, omega, rec.active_nodes, rec.chi_triangles, rec.t_fluid,
                    rec.fluid_reused ? " (reused)" : "", rec.t_structure);
      progress(line);
    }
    if (converged) {
      result.converged = true;
      break;
    }
    warm = &result.structure;
  }
  result.projections = p_.relaxation.projections();
  return result;
}

}  // namespace fsi
