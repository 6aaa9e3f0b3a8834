// The fluid's force on each hole of D by the residual (volume) method (SPEC §10
// "Forces", hole_force) against two independent values, in Stokes flow through a
// channel past two disks (no structure, χ = 0): the inflow on the left, the outflow
// on the right, walls top and bottom, the disks mirror images of each other in the
// channel's centreline y = 0.
//  (1) Mirror symmetry: the flow is symmetric, so the forces are (Fx, Fy) and
//      (Fx, −Fy). Gmsh's meshes are not symmetric, so this holds to discretisation
//      error: the asymmetry must be a small part of what refining changes.
//  (2) The traction integral ∮ σ(v_h, p_h) n ds along each circle, evaluated from the
//      triangles on it: a different formula with a larger error (σ_h is one order
//      less accurate than v_h), so the two must approach each other as h → 0.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/fluid_setup.hpp"
#include "fluid/stokes_residual.hpp"
#include "support/channel.hpp"
#include "support/traction.hpp"

namespace fsi::obstacle_forces_test {
namespace {

constexpr double kMu = 0.0035, kR = 0.1, kYc = 0.2;

FluidParams channel() { return testing::channel(kMu); }

struct Forces {
  Point residual[2], traction[2];
};

Forces solve(double h) {
  const FluidParams f = channel();
  FluidGeometry g{f.L1, f.H1, f.H2, 0, 0, 0, h};
  g.holes = std::vector<FluidHole>{{0.6, kYc, kR}, {0.6, -kYc, kR}};
  const Mesh mesh = generate_fluid_mesh(g);
  PenalisedStokes stokes(mesh, kMu, 1.0, [](const Point&) { return Point(0, 0); }, box_boundary_conditions(mesh, f));
  const FluidSolution& s = stokes.solve();
  const Eigen::VectorXd no_penalty = Eigen::VectorXd::Zero(mesh.num_triangles());
  Forces out;
  for (int i = 0; i < 2; ++i) {
    const int label = mesh.label("Sigma_5_" + std::to_string(i + 1));
    out.residual[i] = hole_force(mesh, kMu, Point::Zero(), s, label, no_penalty);
    out.traction[i] = testing::traction_force(mesh, s, label, kMu);
  }
  return out;
}

TEST(ObstacleForces, ResidualForcesAreMirrorSymmetricAndAgreeWithTheTractionIntegral) {
  const Eigen::Vector2d mirror(1, -1);
  std::vector<double> asymmetry, apart, change;  // relative to |F1|
  Point last = Point::Zero();
  for (double h : {0.04, 0.02, 0.01}) {
    const Forces F = solve(h);
    const double scale = F.residual[0].norm();
    asymmetry.push_back((F.residual[0] - mirror.cwiseProduct(F.residual[1])).norm() / scale);
    apart.push_back((F.traction[0] - F.residual[0]).norm() / scale);
    std::printf("h %.3f: residual F1 (%.6e, %.6e) F2 (%.6e, %.6e); traction F1 (%.6e, %.6e); asymmetry %.2e, "
                "traction - residual %.2e\n",
                h, F.residual[0].x(), F.residual[0].y(), F.residual[1].x(), F.residual[1].y(), F.traction[0].x(),
                F.traction[0].y(), asymmetry.back(), apart.back());
    if (h < 0.04) change.push_back((F.residual[0] - last).norm() / scale);
    last = F.residual[0];
  }
  EXPECT_GT(last.x(), 0) << "the drag points along the flow";
  for (std::size_t k = 0; k + 1 < apart.size(); ++k) {
    // Measured: the forces differ from their mirror images by 1.0e-3 and 7.5e-5 of |F|
    // on the two coarser meshes, 3% and 1% of what the next refinement changes (the
    // discretisation error): the asymmetry is the meshes', nothing systematic.
    EXPECT_LT(asymmetry[k], 0.1 * change[k]) << "h level " << k;
    // Measured rates 2.25 and 1.31 (σ_h's error O(h), the residual's O(h²)).
    EXPECT_GE(std::log2(apart[k] / apart[k + 1]), 0.8) << "the traction integral does not approach the residual force";
  }
}

// Archimedes, exactly: with no flow (Vmax = 0) and gravity f_F, the discrete solution
// is v = 0 with the hydrostatic p = f_y (y + H2) (P1 holds it; p = 0 on the outflow at
// the bottom), so the residual force on each hole is −f_F |B_h|, |B_h| the area of its
// meshed polygon, to round-off: ∑_i R_i = −∮ p n over the polygon, ∑ φ_i = 1 on it.
TEST(ObstacleForces, AtRestEachHoleFeelsItsBuoyancyExactly) {
  FluidParams f = channel();
  f.sides = {"wall", "outflow", "wall", "inflow"}, f.Vmax = 0, f.f = Point(0, -981);
  FluidGeometry g{f.L1, f.H1, f.H2, 0, 0, 0, 0.04};
  g.holes = std::vector<FluidHole>{{0.6, kYc, kR}, {1.3, -kYc, 1.5 * kR}};
  const Mesh mesh = generate_fluid_mesh(g);
  PenalisedStokes stokes(mesh, kMu, 1.0, [&](const Point&) { return f.f; }, box_boundary_conditions(mesh, f));
  const FluidSolution& s = stokes.solve();
  for (int i = 0; i < 2; ++i) {
    const int label = mesh.label("Sigma_5_" + std::to_string(i + 1));
    double area = 0;
    const Point centre((*g.holes)[i].x0, (*g.holes)[i].y0);
    for (const BoundaryEdge& e : mesh.edges_on(label)) {
      const Point a = mesh.vertices[e.v[0]] - centre, b = mesh.vertices[e.v[1]] - centre;
      area += std::abs(a.x() * b.y() - a.y() * b.x()) / 2;
    }
    const Point F = hole_force(mesh, kMu, f.f, s, label, Eigen::VectorXd::Zero(mesh.num_triangles()));
    const double buoyancy = 981 * area;
    std::printf("hole %d: F = (%.3e, %.12e), -f_F |B_h| = (0, %.12e)\n", i + 1, F.x(), F.y(), buoyancy);
    // Round-off: the solve's relative residual is ~1e-15 on pressures of 981 Pa.
    EXPECT_NEAR(F.x(), 0, 1e-10 * buoyancy);
    EXPECT_NEAR(F.y(), buoyancy, 1e-10 * buoyancy);
  }
}

}  // namespace
}  // namespace fsi::obstacle_forces_test
