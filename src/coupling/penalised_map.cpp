#include "coupling/penalised_map.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {
namespace {

[[noreturn]] void fail(const std::string& phase, int k, const std::string& what) {
  throw SolverFailure(phase + " failed at fixed-point iteration " + std::to_string(k) + ": " + what);
}

}  // namespace

MapValue PenalisedMap::operator()(const Eigen::VectorXd& u, int k, const ContactSolution* warm, IterationRecord& rec) {
  const Mesh& reference = p_.structure.mesh();
  const int nv = reference.num_vertices();
  {
    const Stopwatch clock;  // step 2: χ of φ^k(Ω_S0)
    const Eigen::VectorXd chi = p_.chi(displaced(reference, u.head(nv), u.tail(nv)));
    p_.fluid.set_chi(chi);
    rec.chi_triangles = static_cast<int>((chi.array() > 0).count());
    rec.t_chi = clock.elapsed();
  }
  // Steps 2–3: the fluid solve, exact (at least) where the deformed vertices sample
  // it, then b_S from v∘φ^k, p∘φ^k (eq. 33).
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
  Eigen::VectorXd b_S;
  {
    const Stopwatch clock;
    b_S = guarded("the force transfer", k, [&] {
      return Eigen::VectorXd(p_.b_applied + p_.force(sample_at(FluidField(p_.fluid_locator, *fluid), where), u));
    });
    if (!b_S.allFinite()) fail("the force transfer", k, "non-finite load on the structure");
    rec.t_transfer = clock.elapsed() + t_locate;
  }
  MapValue value;
  {
    const Stopwatch clock;  // step 4: the contact QP, warm-started
    value.structure = guarded("the contact QP", k, [&] {
      if (relinearise) relinearise(u);
      return p_.structure.solve(b_S, warm);
    });
    if (!value.structure.u.allFinite()) fail("the contact QP", k, "non-finite displacement");
    value.fluid_load = b_S - p_.b_applied;
    value.load = std::move(b_S);
    rec.newton_steps = value.structure.newton.steps;
    rec.t_structure = clock.elapsed();
  }
  return value;
}

std::string PenalisedMap::describe(const IterationRecord& rec) const {
  char line[160];
  std::snprintf(line, sizeof line, "active %2d  chi %5d  fluid %.3f s%s  structure %.4f s", rec.active_nodes,
                rec.chi_triangles, rec.t_fluid, rec.fluid_reused ? " (reused)" : "", rec.t_structure);
  return line;
}

}  // namespace fsi
