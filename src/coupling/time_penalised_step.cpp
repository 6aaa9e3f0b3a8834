#include "coupling/time_penalised_step.hpp"

#include <cstdio>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "coupling/phase_guard.hpp"
#include "fem/p1.hpp"
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
// for an area fraction's triangle whose barycentre lies outside); and χ_T div ũ̇ there
// (constant on the structure's P1 triangle, in the deformed coordinates).
Eigen::Matrix2Xd TimePenalisedStep::chi_velocity(const Eigen::VectorXd& chi, const Mesh& deformed,
                                                 const Eigen::VectorXd& u_dot, Eigen::VectorXd& chi_div) {
  const Mesh& fluid = p_.fluid.mesh();
  Eigen::Matrix2Xd out = Eigen::Matrix2Xd::Zero(2, fluid.num_triangles());
  chi_div = Eigen::VectorXd::Zero(fluid.num_triangles());
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
    const P1Triangle S(deformed, at.triangle);
    for (int c = 0; c < 2; ++c)
      for (int a = 0; a < 3; ++a) {
        out(c, t) += chi[t] * at.lambda[a] * u_dot[dof(s[a], c, nv)];
        chi_div[t] += chi[t] * S.grad(a, c) * u_dot[dof(s[a], c, nv)];
      }
  }
  return out;
}

// The penalty's reaction (1/ε) Σ_T χ_T ∫_T (v_h − ū_T)·w̃_i on the structure's dofs, w̃_i
// the fluid-space interpolant of the structure's basis function φ_i (its values at the
// fluid vertices, each located in the deformed structure or at its nearest point), the
// integrals exact as the fluid's own mass term has them (P1 and bubble parts).
Eigen::VectorXd TimePenalisedStep::penalty_force(const FluidSolution& v, const Eigen::Matrix2Xd& chi_u) const {
  const Mesh& fluid = p_.fluid.mesh();
  const int nv = p_.structure.num_vertices();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * nv);
  const Mesh deformed = displaced(p_.structure, last_u_.head(nv), last_u_.tail(nv));
  const PointLocator inside(deformed);
  std::unordered_map<int, Location> at;  // fluid vertex → where w̃ is read
  for (const Inside& in : inside_) {
    const int t = in.fluid;
    const auto& tri = fluid.triangles[t];
    const double area = fluid.area(t), kappa = in.chi / p_.fluid.eps();
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector2d q = -chi_u.col(t) / in.chi * (area / 3) + v.bubble.col(t) * bubble::p1_times_bubble(area);
      for (int b = 0; b < 3; ++b) q += bubble::mass_p1(area, a, b) * Eigen::Vector2d(v.v1[tri[b]], v.v2[tri[b]]);
      auto it = at.find(tri[a]);
      if (it == at.end()) it = at.emplace(tri[a], inside.locate_or_nearest(fluid.vertices[tri[a]])).first;
      const auto& s = deformed.triangles[it->second.triangle];
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 3; ++k) f[dof(s[k], c, nv)] += kappa * q[c] * it->second.lambda[k];
    }
  }
  return f;
}

Eigen::VectorXd TimePenalisedStep::load(const Eigen::VectorXd& u, int k, IterationRecord& rec) {
  const Mesh& reference = p_.structure;
  const int nv = reference.num_vertices();
  const Eigen::VectorXd u_dot = velocity(u);  // on the structure's dofs (P2: its nodes)
  last_u_ = u;
  std::vector<int> sampled;  // χ's support: where the force reads the fluid (penalty_force)
  {
    const Stopwatch clock;  // χ and the penalty's velocity at φ(Ω_S0)
    const Mesh deformed = displaced(reference, u.head(nv), u.tail(nv));
    const Eigen::VectorXd chi = p_.chi(deformed);
    p_.fluid.set_chi(chi);
    Eigen::VectorXd chi_div;
    Eigen::Matrix2Xd chi_u = chi_velocity(chi, deformed, u_dot, chi_div);
    p_.penalty.set(std::move(chi_u), std::move(chi_div));
    p_.fluid.near_terms_changed();  // the penalty's velocity: zero where χ = 0
    for (int t = 0; t < chi.size(); ++t)
      if (chi[t] != 0) sampled.push_back(t);
    rec.chi_triangles = static_cast<int>(sampled.size());
    rec.t_chi = clock.elapsed();
  }
  const FluidSolution* fluid = nullptr;
  {
    const Stopwatch clock;
    fluid = guarded("the fluid's time step", k, [&] { return &p_.stepper.solve(&sampled); });
    rec.t_fluid = clock.elapsed();
  }
  const Stopwatch clock;
  Eigen::VectorXd load = guarded("the force transfer", k, [&] {
    return penalty_force(*fluid, p_.penalty.chi_velocity());
  });
  rec.t_transfer = clock.elapsed();
  return load;
}

std::string TimePenalisedStep::describe(const IterationRecord& rec) const {
  char line[160];
  std::snprintf(line, sizeof line, "active %2d  chi %5d  fluid %.3f s  structure %.4f s", rec.active_nodes,
                rec.chi_triangles, rec.t_fluid, rec.t_structure);
  return line;
}

}  // namespace fsi
