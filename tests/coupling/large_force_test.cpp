// coupling.force = "large" (SPEC §11): the exact pull-back of the fluid's force. For a
// prescribed deformation (a P1 φ, here a bend and a shear far beyond small
// displacements) and prescribed fluid fields at the deformed vertices, the pulled-back
// load equals the integrals of eq. (33)'s small form taken directly on the deformed
// triangles φ(T), with the test functions carried by φ (change of variables, exact for
// an affine φ on each triangle); and it tends to the small form as u → 0.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/force_transfer.hpp"
#include "solid/elasticity.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::large_force_test {
namespace {

constexpr double kMu = 0.0035, kEps = 1e-3;
const Point kF(0.3, -9.81e3);

Mesh reference() { return testing::structured_rectangle(0.3, 0.03, 12, 3); }

// u = s·(bend + shear): φ(X, Y) rotates the beam's sections about (0, −R) and shears it.
Eigen::VectorXd deformation(const Mesh& mesh, double s) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd u(2 * nv);
  for (int v = 0; v < nv; ++v) {
    const double X = mesh.vertices[v].x(), Y = mesh.vertices[v].y(), R = 0.25, a = X / R;
    const Point bent((R + Y) * std::sin(a), (R + Y) * std::cos(a) - R);
    const Point d = bent - mesh.vertices[v] + Point(0.4 * Y, 0.1 * X * X);
    u[v] = s * d.x(), u[nv + v] = s * d.y();
  }
  return u;
}

SampledFluid fields(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  SampledFluid f{Eigen::VectorXd(2 * nv), Eigen::VectorXd(nv)};
  for (int v = 0; v < nv; ++v) {
    const Point& X = mesh.vertices[v];
    f.v[v] = 0.2 * std::sin(7 * X.x()) + X.y(), f.v[nv + v] = -0.1 * std::cos(5 * X.x() + 20 * X.y());
    f.p[v] = -500 + 300 * X.x() * X.x() - 40 * X.y();
  }
  return f;
}

// eq. (33)'s small form assembled on the deformed mesh: ∫ 2μ ε(v):ε(w) − ∫ p div w
// + (1/ε) ∫ v·w − ∫ f·w over φ(Ω_S0).
Eigen::VectorXd on_the_deformed_mesh(const Mesh& mesh, const Eigen::VectorXd& u, const SampledFluid& s) {
  const int nv = mesh.num_vertices();
  Mesh deformed = mesh;
  for (int v = 0; v < nv; ++v) deformed.vertices[v] += Point(u[v], u[nv + v]);
  return assemble_elasticity(deformed, Lame{0.0, kMu}) * s.v - assemble_divergence(deformed) * s.p +
         assemble_vector_mass(deformed) * s.v / kEps -
         assemble_volume_load(deformed, [](const Point&) { return kF; }, 2);
}

TEST(LargeForce, IsTheSmallFormOnTheDeformedConfiguration) {
  const Mesh mesh = reference();
  const SampledFluid s = fields(mesh);
  const FluidForce large(mesh, kMu, kEps, [](const Point&) { return kF; }, ForceModel::large);
  const FluidForce small(mesh, kMu, kEps, [](const Point&) { return kF; }, ForceModel::small);
  const Eigen::VectorXd u = deformation(mesh, 1.0);
  const Eigen::VectorXd expected = on_the_deformed_mesh(mesh, u, s);
  const Eigen::VectorXd got = large(s, u);
  EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-11 * expected.cwiseAbs().maxCoeff());
  // The deformation is large: the small form misses by far more than round-off.
  EXPECT_GT((small(s, u) - expected).cwiseAbs().maxCoeff(), 1e-2 * expected.cwiseAbs().maxCoeff());
}

TEST(LargeForce, TendsToTheSmallFormAsTheDisplacementVanishes) {
  const Mesh mesh = reference();
  const SampledFluid s = fields(mesh);
  const FluidForce large(mesh, kMu, kEps, [](const Point&) { return kF; }, ForceModel::large);
  const FluidForce small(mesh, kMu, kEps, [](const Point&) { return kF; }, ForceModel::small);
  double last = 0;
  for (double scale : {1e-2, 5e-3, 2.5e-3}) {
    const Eigen::VectorXd u = deformation(mesh, scale);
    const double gap = (large(s, u) - small(s, u)).norm() / small(s, u).norm();
    if (last > 0) {
      EXPECT_NEAR(last / gap, 2.0, 0.05) << "first order in u, scale " << scale;
    }
    last = gap;
  }
}

}  // namespace
}  // namespace fsi::large_force_test
