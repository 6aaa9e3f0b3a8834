#include "coupling/penalised_step.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

Eigen::VectorXd PenalisedStep::load(const Eigen::VectorXd& u, int k, IterationRecord& rec) {
  const Mesh& reference = p_.structure;
  const int nv = reference.num_vertices();
  {
    const Stopwatch clock;  // step 2: χ of φ^k(Ω_S0)
    const Eigen::VectorXd chi = p_.chi(displaced(reference, u.head(nv), u.tail(nv)));
    p_.fluid.set_chi(chi);
    rec.chi_triangles = static_cast<int>((chi.array() > 0).count());
    rec.t_chi = clock.elapsed();
  }
  // Steps 2–3: the fluid solve, exact (at least) where the deformed vertices sample
  // it, then the load from v∘φ^k, p∘φ^k (eq. 33).
  const Stopwatch located;
  const std::vector<Location> where =
      locate_deformed_vertices(p_.fluid_locator, p_.force.sample_mesh(), p_.force.to_samples(u));
  const double t_locate = located.elapsed();
  const FluidSolution* fluid = nullptr;
  {
    const Stopwatch clock;
    const int reused_before = p_.fluid.timing().reused;
    const std::vector<int> sampled = triangles_of(where);
    fluid = guarded("the fluid solve", k, [&] { return &p_.fluid.solve(&sampled); });
    rec.fluid_reused = p_.fluid.timing().reused > reused_before;
    rec.t_fluid = clock.elapsed();
  }
  const Stopwatch clock;
  Eigen::VectorXd load = guarded("the force transfer", k, [&] {
    return Eigen::VectorXd(p_.force(sample_at(FluidField(p_.fluid_locator, *fluid), where), u));
  });
  rec.t_transfer = clock.elapsed() + t_locate;
  return load;
}

std::string PenalisedStep::describe(const IterationRecord& rec) const {
  char line[160];
  std::snprintf(line, sizeof line, "active %2d  chi %5d  fluid %.3f s%s  structure %.4f s", rec.active_nodes,
                rec.chi_triangles, rec.t_fluid, rec.fluid_reused ? " (reused)" : "", rec.t_structure);
  return line;
}

}  // namespace fsi
