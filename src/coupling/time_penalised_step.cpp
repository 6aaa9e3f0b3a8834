#include "coupling/time_penalised_step.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/phase_guard.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

void TimePenalisedStep::begin_step(const Eigen::VectorXd& u_n, const Eigen::VectorXd& v_n) {
  u_n_ = u_n;
  v_n_ = v_n;
}

Eigen::VectorXd TimePenalisedStep::velocity(const Eigen::VectorXd& u) const {
  return 2.0 / p_.stepper.dt() * (u - u_n_) - v_n_;
}

// χ_T ũ̇(x_T) on the fluid triangles with χ > 0, x_T the barycentre, ũ̇ interpolated in
// the deformed structure's triangle that holds x_T (the nearest one's boundary point
// for an area fraction's triangle whose barycentre lies outside).
Eigen::Matrix2Xd TimePenalisedStep::chi_velocity(const Eigen::VectorXd& chi, const Mesh& deformed,
                                                 const Eigen::VectorXd& u_dot) {
  const Mesh& fluid = p_.fluid.mesh();
  Eigen::Matrix2Xd out = Eigen::Matrix2Xd::Zero(2, fluid.num_triangles());
  inside_.clear();
  if (!(chi.array() > 0).any()) return out;
  const PointLocator inside(deformed);
  const int nv = deformed.num_vertices();
  for (int t = 0; t < fluid.num_triangles(); ++t) {
    if (!(chi[t] > 0)) continue;
    const auto& tri = fluid.triangles[t];
    const Point x = (fluid.vertices[tri[0]] + fluid.vertices[tri[1]] + fluid.vertices[tri[2]]) / 3;
    const Location at = inside.locate_or_nearest(x);
    inside_.push_back({t, chi[t], at});
    const auto& s = deformed.triangles[at.triangle];
    for (int c = 0; c < 2; ++c)
      for (int a = 0; a < 3; ++a) out(c, t) += chi[t] * at.lambda[a] * u_dot[dof(s[a], c, nv)];
  }
  return out;
}

// (1/ε) Σ_T χ_T |T| (v_h(x_T) − ū_T)·φ_i(X_T) on the structure's dofs (chi_u: χ_T ū_T).
Eigen::VectorXd TimePenalisedStep::penalty_force(const FluidSolution& v, const Eigen::Matrix2Xd& chi_u) const {
  const Mesh& fluid = p_.fluid.mesh();
  const Mesh& structure = p_.structure;
  const int nv = structure.num_vertices();
  const FluidField field(p_.fluid_locator, v);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * nv);
  for (const Inside& in : inside_) {
    const Location centre{in.fluid, Eigen::Vector3d::Constant(1.0 / 3)};
    const Point mismatch = in.chi * field.at(centre).v - chi_u.col(in.fluid);
    const double weight = fluid.area(in.fluid) / p_.fluid.eps();
    const auto& s = structure.triangles[in.at.triangle];
    for (int c = 0; c < 2; ++c)
      for (int a = 0; a < 3; ++a) f[dof(s[a], c, nv)] += weight * mismatch[c] * in.at.lambda[a];
  }
  return f;
}

// ρ_F ∂ṽ/∂t at the samples: (α ṽ^{n+1} − β₁ ṽ^n − β₂ ṽ^{n−1}) ρ_F/Δt, each field read at
// the deformed sample points.
Eigen::VectorXd TimePenalisedStep::inertia_at(const std::vector<Location>& where, const FluidSolution& v_next) const {
  const BdfWeights w = p_.stepper.weights();
  const PointLocator& L = p_.fluid_locator;
  Eigen::VectorXd d = w.alpha * sample_at(FluidField(L, v_next), where).v -
                      w.beta1 * sample_at(FluidField(L, p_.stepper.state()), where).v;
  if (w.beta2 != 0) d -= w.beta2 * sample_at(FluidField(L, p_.stepper.previous()), where).v;
  return p_.rho / p_.stepper.dt() * d;
}

Eigen::VectorXd TimePenalisedStep::load(const Eigen::VectorXd& u, int k, IterationRecord& rec) {
  const Mesh& reference = p_.structure;
  const int nv = reference.num_vertices();
  const Eigen::VectorXd u_dot = velocity(u);  // on the structure's dofs (P2: its nodes)
  {
    const Stopwatch clock;  // χ and the penalty's velocity at φ(Ω_S0)
    const Mesh deformed = displaced(reference, u.head(nv), u.tail(nv));
    const Eigen::VectorXd chi = p_.chi(deformed);
    p_.fluid.set_chi(chi);
    p_.penalty.set(chi_velocity(chi, deformed, u_dot));
    p_.fluid.terms_changed();
    rec.chi_triangles = static_cast<int>((chi.array() > 0).count());
    rec.t_chi = clock.elapsed();
  }
  const Stopwatch located;
  const std::vector<Location> where =
      locate_deformed_vertices(p_.fluid_locator, p_.force.sample_mesh(), p_.force.to_samples(u));
  const double t_locate = located.elapsed();
  const FluidSolution* fluid = nullptr;
  {
    const Stopwatch clock;
    fluid = guarded("the fluid's time step", k, [&] { return &p_.stepper.solve(); });
    rec.t_fluid = clock.elapsed();
  }
  const Stopwatch clock;
  Eigen::VectorXd load = guarded("the force transfer", k, [&] {
    const SampledFluid sampled = sample_at(FluidField(p_.fluid_locator, *fluid), where);
    // Eq. (33) without its penalty term (1/ε) M ṽ, plus the inertia, plus the penalty's reaction.
    const Eigen::VectorXd extra = -sampled.v / p_.fluid.eps() + inertia_at(where, *fluid);
    return Eigen::VectorXd(p_.force(sampled, u) + p_.force.mass_load(extra) +
                           penalty_force(*fluid, p_.penalty.chi_velocity()));
  });
  rec.t_transfer = clock.elapsed() + t_locate;
  return load;
}

std::string TimePenalisedStep::describe(const IterationRecord& rec) const {
  char line[160];
  std::snprintf(line, sizeof line, "active %2d  chi %5d  fluid %.3f s  structure %.4f s", rec.active_nodes,
                rec.chi_triangles, rec.t_fluid, rec.t_structure);
  return line;
}

}  // namespace fsi
