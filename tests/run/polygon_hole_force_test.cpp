// The fluid's force on a polygon hole of D by the residual method (SPEC §10 "Forces",
// hole_force), the fluid alone (χ = 0) in a channel: inflow on the left, outflow on
// the right, walls top and bottom, a square hole turned by 30° and a triangle.
//  (1) Archimedes, exactly: with no flow and gravity f_F the discrete solution is the
//      hydrostatic one (P1 holds it), so the force on each hole is −f_F |P| with |P|
//      the polygon's own area (a polygon is meshed exactly), to round-off.
//  (2) With flow, the traction integral ∮ σ(v_h, p_h) n ds over the square's edges
//      (support/traction.hpp), an independent formula, approaches the residual force
//      as the mesh is refined. The convex corners are re-entrant corners of the
//      fluid, where σ is singular (about r^(λ−1), λ = 0.5445 for Stokes flow in a
//      270° corner), so σ_h's error falls more slowly there than on a circle.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/polygon.hpp"
#include "run/fluid_setup.hpp"
#include "fluid/stokes_residual.hpp"
#include "support/channel.hpp"
#include "support/traction.hpp"

namespace fsi::polygon_hole_force_test {
namespace {

constexpr double kMu = 0.0035;

FluidParams channel() { return testing::channel(kMu); }

std::vector<Point> square() {
  std::vector<Point> p;
  for (int k = 0; k < 4; ++k) {
    const double t = M_PI / 6 + k * M_PI / 2;
    p.emplace_back(0.6 + 0.12 * std::cos(t), 0.1 + 0.12 * std::sin(t));
  }
  return p;
}

const std::vector<Point> kTriangle = {{1.2, -0.3}, {1.4, -0.3}, {1.3, -0.1}};

Mesh channel_mesh(double h) {
  const FluidParams f = channel();
  FluidGeometry g{f.L1, f.H1, f.H2, 0, 0, 0, h};
  g.holes = std::vector<FluidHole>{{0, 0, 0, square()}, {0, 0, 0, kTriangle}};
  return generate_fluid_mesh(g);
}

TEST(PolygonHoleForce, AtRestEachPolygonFeelsItsBuoyancyExactly) {
  FluidParams f = channel();
  f.sides = {"wall", "outflow", "wall", "inflow"}, f.Vmax = 0, f.f = Point(0, -981);
  const Mesh mesh = channel_mesh(0.04);
  PenalisedStokes stokes(mesh, kMu, 1.0, [&](const Point&) { return f.f; }, box_boundary_conditions(mesh, f));
  const FluidSolution& s = stokes.solve();
  const std::vector<Point> polygons[] = {square(), kTriangle};
  for (int i = 0; i < 2; ++i) {
    const Point F = hole_force(mesh, kMu, f.f, s, mesh.label("Sigma_5_" + std::to_string(i + 1)),
                               Eigen::VectorXd::Zero(mesh.num_triangles()));
    const double buoyancy = 981 * std::abs(signed_area(polygons[i]));
    std::printf("polygon %d: F = (%.3e, %.12e), 981 |P| = %.12e\n", i + 1, F.x(), F.y(), buoyancy);
    // Round-off: the solve's relative residual is ~1e-15 on pressures of 981 Pa.
    EXPECT_NEAR(F.x(), 0, 1e-10 * buoyancy);
    EXPECT_NEAR(F.y(), buoyancy, 1e-10 * buoyancy);
  }
}

TEST(PolygonHoleForce, TheTractionIntegralApproachesTheResidualForce) {
  const FluidParams f = channel();
  std::vector<double> apart;  // |traction − residual| / |residual|
  Point last = Point::Zero();
  for (double h : {0.02, 0.01, 0.005}) {
    const Mesh mesh = channel_mesh(h);
    PenalisedStokes stokes(mesh, kMu, 1.0, [](const Point&) { return Point(0, 0); }, box_boundary_conditions(mesh, f));
    const FluidSolution& s = stokes.solve();
    const int label = mesh.label("Sigma_5_1");
    const Point R = hole_force(mesh, kMu, Point::Zero(), s, label, Eigen::VectorXd::Zero(mesh.num_triangles()));
    const Point T = testing::traction_force(mesh, s, label, kMu);
    apart.push_back((T - R).norm() / R.norm());
    std::printf("h %.3f: residual (%.8e, %.8e), traction (%.8e, %.8e), apart %.3e\n", h, R.x(), R.y(), T.x(), T.y(),
                apart.back());
    last = R;
  }
  EXPECT_GT(last.x(), 0) << "the drag points along the flow";
  // Measured: 8.2 %, 5.1 %, 2.7 % apart, rates 0.69 and 0.92 (and 0.73 % at h =
  // 0.0025; at h = 0.04, 8.2 % too: pre-asymptotic); the corners' singularity bounds
  // the rate near λ = 0.54 on average (a smooth boundary gives 1 or more, obstacle_
  // forces_test.cpp). A force that missed part of the hole's boundary would stay
  // apart: rate 0.
  for (std::size_t k = 0; k + 1 < apart.size(); ++k)
    EXPECT_GE(std::log2(apart[k] / apart[k + 1]), 0.5) << "the traction integral does not approach the residual force";
}

}  // namespace
}  // namespace fsi::polygon_hole_force_test
