// A manufactured Stokes solution for the mini element (χ = 0), the one of
// stokes_mms_test.cpp: v = curl of a stream function (divergence-free), a smooth
// pressure, f = −μΔv + ∇p, v prescribed on the Dirichlet parts and the exact traction
// σ(v,p)n on the outlet (normal (0, −1), the paper's box's bottom). Shared with the
// PETSc solvers' test, which runs it through the parallel path.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fluid/penalised_stokes.hpp"
#include "support/stokes_norms.hpp"

namespace fsi::testing::stokes_mms {

inline constexpr double pi = std::numbers::pi;
inline constexpr double mu = 1.0;

inline Point v_exact(const Point& x) {
  return {std::sin(pi * x.x()) * std::cos(pi * x.y()), -std::cos(pi * x.x()) * std::sin(pi * x.y())};
}
inline Eigen::Matrix2d grad_v(const Point& x) {
  Eigen::Matrix2d g;
  const double sx = std::sin(pi * x.x()), cx = std::cos(pi * x.x()), sy = std::sin(pi * x.y()),
               cy = std::cos(pi * x.y());
  g << pi * cx * cy, -pi * sx * sy, pi * sx * sy, -pi * cx * cy;
  return g;
}
inline double p_exact(const Point& x) { return std::cos(pi * x.x()) * std::exp(x.y()); }
inline Point grad_p(const Point& x) {
  return {-pi * std::sin(pi * x.x()) * std::exp(x.y()), std::cos(pi * x.x()) * std::exp(x.y())};
}
// −div(2μ ε(v)) + ∇p = −μΔv + ∇p, and Δv = −2π² v for this v.
inline Point body_force(const Point& x) { return 2 * pi * pi * mu * v_exact(x) + grad_p(x); }
inline Point traction(const Point& x, const Point& n) {
  const Eigen::Matrix2d g = grad_v(x);
  return (-p_exact(x) * Eigen::Matrix2d::Identity() + mu * (g + g.transpose())) * n;
}

// The errors of the solve on `mesh` with the given Dirichlet and outlet labels; the
// linear solver set by `configure` (none: the default).
template <class Configure>
StokesErrors solve(const Mesh& mesh, const std::vector<std::string>& dirichlet, const std::string& outlet,
                   Configure configure) {
  FluidBoundaryConditions bc;
  for (const auto& name : dirichlet) bc.dirichlet_labels.push_back(mesh.label(name));
  bc.g = v_exact;
  bc.tractions.emplace_back(mesh.label(outlet), [](const Point& x) { return traction(x, Point(0, -1)); });
  PenalisedStokes stokes(mesh, mu, 1.0, body_force, bc);
  configure(stokes);
  return mini_errors(mesh, stokes.solve(), v_exact, grad_v, p_exact);
}
inline StokesErrors solve(const Mesh& mesh, const std::vector<std::string>& dirichlet, const std::string& outlet) {
  return solve(mesh, dirichlet, outlet, [](PenalisedStokes&) {});
}

}  // namespace fsi::testing::stokes_mms
