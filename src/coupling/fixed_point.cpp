#include "coupling/fixed_point.hpp"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "coupling/pass_steps.hpp"
#include "coupling/phase_guard.hpp"

namespace fsi {

FixedPointCoupling::FixedPointCoupling(Parts parts, double tol, int max_iterations)
    : p_(parts), tol_(tol), max_iterations_(max_iterations),
      M_(assemble_vector_mass(parts.structure.mesh())) {
  p_.relaxation.project = [this](const Eigen::VectorXd& z) { return p_.structure.project(z); };
}

std::string convergence_warning(const CouplingResult& r, double tol) {
  const std::size_t n = r.history.size();
  if (r.converged && r.final_norm > 0 && r.final_increment > 0.1 * r.final_norm) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "the stop says little: the last increment %.2e is %.0f%% of the displacement's own L2 norm "
                  "%.2e, so tol %g is coarse for this problem's scale; a smaller coupling.tol",
                  r.final_increment, 100 * r.final_increment / r.final_norm, r.final_norm, tol);
    return text;
  }
  if (!r.converged || n < 11) return "";
  std::vector<double> previous;
  for (std::size_t i = n - 11; i + 1 < n; ++i) previous.push_back(r.history[i].increment);
  std::nth_element(previous.begin(), previous.begin() + 5, previous.end());
  const double median = previous[5];
  const double last = r.history[n - 1].increment;
  const double before = std::max({r.history[n - 2].increment, r.history[n - 3].increment, r.history[n - 4].increment});
  if (median <= 5 * tol || last >= 0.1 * before) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "the increments had not settled (median of the ten before the last %.2e, tol %g) and "
                "fell abruptly (largest of the three before the last %.2e, the last %.2e): the stop may "
                "be a chance dip below tol; see history.csv",
                median, tol, before, last);
  return text;
}

CouplingResult FixedPointCoupling::run() {
  CouplingResult result;
  result.structure = p_.structure.at_rest();  // the last good state if the first pass fails
  try {
    iterate(result);
  } catch (const SolverFailure& e) {
    result.failure = e.what();
  }
  // The outputs need the fields everywhere: the last fluid solve's deferred
  // expansion to the far field.
  if (complete_at_end && p_.fluid.has_solution()) {
    try {
      p_.fluid.complete();
    } catch (const SolverFailure& e) {
      if (result.failure.empty()) result.failure = std::string("the fluid solve (far field) failed: ") + e.what();
    }
  }
  result.projections = p_.relaxation.projections();
  return result;
}

void FixedPointCoupling::iterate(CouplingResult& result) {
  const Mesh& reference = p_.structure.mesh();
  const int nv = reference.num_vertices();
  Eigen::VectorXd u = initial_iterate(p_.structure, initial);
  const ContactSolution* warm = nullptr;
  auto fail = [&](const std::string& phase, const std::string& what) {
    throw SolverFailure(phase + " failed at fixed-point iteration " +
                        std::to_string(result.iterations) + ": " + what);
  };

  // Where the structure is likely to go: under its applied loads alone (with
  // contact), it moves as it will with the fluid's force added, in the paper's cases.
  // The fluid's first near region covers that too (one far-field factorisation
  // instead of two); a poor guess costs only a larger region or a second one.
  try {
    const ContactSolution guess = p_.structure.solve(p_.b_applied);
    if (guess.u.allFinite())
      p_.fluid.set_region_hint(p_.chi(displaced(reference, guess.u.head(nv), guess.u.tail(nv))));
  } catch (const QpError&) {  // no hint: the region grows when needed; pass 1's QP will say why
  }

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
      fluid = guarded("the fluid solve", k, [&] { return &p_.fluid.solve(/*near_only=*/true); });
      rec.fluid_reused = p_.fluid.timing().reused > reused_before;
      rec.t_fluid = clock.elapsed();
    }
    Eigen::VectorXd b_S;
    {
      const Stopwatch clock;  // step 3: b_S from v∘φ^k, p∘φ^k (eq. 33)
      auto load = [&](const FluidSolution& f) {
        const FluidField field(p_.fluid_locator, f);
        return Eigen::VectorXd(p_.b_applied + p_.force(sample_at_deformed_vertices(field, reference, u), u));
      };
      b_S = guarded("the force transfer", k, [&] {
        try {
          return load(*fluid);
        } catch (const FieldNotComputed&) {  // a vertex samples the far field: expand
          return load(p_.fluid.complete());
        }
      });
      if (!b_S.allFinite()) fail("the force transfer", "non-finite load on the structure");
      rec.t_transfer = clock.elapsed();
    }
    {
      const Stopwatch clock;  // step 4: the contact QP, warm-started
      ContactSolution next = guarded("the contact QP", k, [&] {
        if (relinearise) relinearise(u);
        return p_.structure.solve(b_S, warm);
      });
      if (!next.u.allFinite()) fail("the contact QP", "non-finite displacement");
      result.structure = std::move(next);  // only a good state replaces the last one
      result.fluid_load = b_S - p_.b_applied;
      rec.t_structure = clock.elapsed();
    }
    const Eigen::VectorXd d = result.structure.u - u;  // step 5
    rec.increment = std::sqrt(d.dot(M_ * d));
    if (!std::isfinite(rec.increment)) fail("the stopping test", "the increment is not a finite number");
    rec.active_nodes = result.structure.qp.active_count();
    result.final_increment = rec.increment;
    result.final_norm = std::sqrt(result.structure.u.dot(M_ * result.structure.u));
    const bool converged = rec.increment < tol_;
    result.history.push_back(rec);  // recorded before relaxing: kept if that fails
    if (!converged && k < max_iterations_) {
      u = relaxed_iterate(p_.relaxation, u, result.structure.u, k, rec, result);
    }
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
      return;
    }
    if (interrupt_requested()) {
      result.interrupted = true;
      if (progress) progress("[coupling] interrupted (Ctrl-C): stopping after iteration " + std::to_string(k));
      return;
    }
    warm = &result.structure;
  }
}

}  // namespace fsi
