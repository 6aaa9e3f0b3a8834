// Which model of the fluid's force each method solves (issue 27, "the x load"): a
// structure moved rigidly (rotated by θ, translated) in a fluid at rest, whose
// hydrostatic pressure p = p0 + f_F·x (∇p = f_F) is linear, so every P1 integral
// below is exact and the exact load is known: the pressure on the deformed outline,
//     b_k = −∫_{∂φ(Ω)} p n W_k ds   (zero at interior vertices, Archimedes in total).
// - "large" (the exact pull-back) and the body-fitted method's deformed-normal
//   traction give it;
// - eq. (33)'s small form gives the reference-normal traction −∫_{∂Ω0} p̃ N w_k plus
//   the body force ∫ (Fᵀ − I) ∇p · w_k: the right total, but a spurious load at the
//   interior vertices;
// - the body-fitted method's default (the pressure with the reference normal) gives
//   the first term alone: zero at the interior vertices, its total turned by Rᵀ.
// So the penalised and the body-fitted checks compare like with like only with
// coupling.force = "large" on both (docs/validation.md, "The penalty's error").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling/body_fitted_force.hpp"
#include "coupling/force_transfer.hpp"
#include "fem/vector_p1.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::force_models_test {
namespace {

constexpr double kMu = 0.0035, kEps = 1e-5, kTheta = 0.2, kP0 = -500;
const Point kF(0.0, -981.0), kShift(0.01, -0.02);
constexpr int kNx = 12, kNy = 3;

struct Rigid {
  Mesh mesh = testing::structured_rectangle(0.3, 0.03, kNx, kNy);
  Eigen::Matrix2d R;
  Eigen::VectorXd u;
  SampledFluid s;  // v = 0, p̃ = p∘φ
  std::vector<int> outline;  // the boundary, counter-clockwise from (0, 0), closed
  Rigid() {
    R << std::cos(kTheta), -std::sin(kTheta), std::sin(kTheta), std::cos(kTheta);
    const int nv = mesh.num_vertices();
    u.resize(2 * nv);
    s = {Eigen::VectorXd::Zero(2 * nv), Eigen::VectorXd(nv)};
    for (int v = 0; v < nv; ++v) {
      const Point x = R * mesh.vertices[v] + kShift;
      u[v] = x.x() - mesh.vertices[v].x(), u[nv + v] = x.y() - mesh.vertices[v].y();
      s.p[v] = kP0 + kF.dot(x);
    }
    auto id = [](int i, int j) { return j * (kNx + 1) + i; };
    for (int i = 0; i < kNx; ++i) outline.push_back(id(i, 0));
    for (int j = 0; j < kNy; ++j) outline.push_back(id(kNx, j));
    for (int i = kNx; i > 0; --i) outline.push_back(id(i, kNy));
    for (int j = kNy; j > 0; --j) outline.push_back(id(0, j));
  }
  // −∫ p̃ n w_k ds along the closed outline, on the reference (X) or deformed (x) points.
  Eigen::VectorXd pressure_load(bool deformed) const {
    const int nv = mesh.num_vertices();
    std::vector<Point> points;
    Eigen::VectorXd p(outline.size() + 1);
    for (std::size_t k = 0; k <= outline.size(); ++k) {
      const int v = outline[k % outline.size()];
      points.push_back(mesh.vertices[v] + (deformed ? Point(u[v], u[nv + v]) : Point(0, 0)));
      p[static_cast<Eigen::Index>(k)] = s.p[v];
    }
    const Eigen::Matrix2Xd F = pressure_nodal_forces(points, p);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * nv);
    for (std::size_t k = 0; k <= outline.size(); ++k)
      for (int c = 0; c < 2; ++c) b[dof(outline[k % outline.size()], c, nv)] += F(c, static_cast<Eigen::Index>(k));
    return b;
  }
  FluidForce force(ForceModel model) const {
    return FluidForce(mesh, kMu, kEps, [](const Point&) { return kF; }, model);
  }
};

Point total(const Eigen::VectorXd& b) {
  const Eigen::Index nv = b.size() / 2;
  return Point(b.head(nv).sum(), b.tail(nv).sum());
}

double max_abs(const Eigen::VectorXd& b) { return b.cwiseAbs().maxCoeff(); }

TEST(ForceModels, TheExactPullBackIsThePressureOnTheDeformedOutline) {
  const Rigid r;
  const Eigen::VectorXd exact = r.pressure_load(true);
  const Eigen::VectorXd large = r.force(ForceModel::large)(r.s, r.u);
  EXPECT_LT(max_abs(large - exact), 1e-10 * max_abs(exact));
  // Archimedes: the total is −|Ω| f_F whatever the motion.
  const Point buoyancy = -0.3 * 0.03 * kF;
  EXPECT_LT((total(exact) - buoyancy).norm(), 1e-10 * buoyancy.norm());
}

TEST(ForceModels, TheSmallFormIsTheReferenceNormalTractionPlusARotatedBodyForce) {
  const Rigid r;
  const Eigen::VectorXd small = r.force(ForceModel::small)(r.s, r.u);
  const Eigen::VectorXd reference_normal = r.pressure_load(false);
  // F = R here, ∇p = f_F: the body force (Rᵀ − I) f_F tested with each w_k.
  const Point body = (r.R.transpose() - Eigen::Matrix2d::Identity()) * kF;
  const Eigen::VectorXd extra = assemble_volume_load(r.mesh, [body](const Point&) { return body; }, 2);
  EXPECT_LT(max_abs(small - reference_normal - extra), 1e-10 * max_abs(small));
  // Neither is the exact load: the small form loads the interior vertices (the
  // vertex at (0.1, 0.01) bears (Rᵀ − I) f_F times its hat's area), the reference
  // normal turns the buoyancy by Rᵀ; the small form's total is the exact one.
  const Eigen::VectorXd exact = r.pressure_load(true);
  const int nv = r.mesh.num_vertices(), interior = 1 * (kNx + 1) + 4;
  const double hat = 0.3 / kNx * 0.03 / kNy;  // ∫ w_k: six triangles of area dx dy / 2, a third each
  EXPECT_NEAR(small[dof(interior, 0, nv)], body.x() * hat, 1e-10 * std::abs(body.x() * hat));
  EXPECT_EQ(exact[dof(interior, 0, nv)], 0.0);
  EXPECT_LT((total(small) - total(exact)).norm(), 1e-10 * total(exact).norm());
  const Point turned = r.R.transpose() * total(exact);
  EXPECT_LT((total(reference_normal) - turned).norm(), 1e-10 * turned.norm());
  EXPECT_GT((total(reference_normal) - total(exact)).norm(), 0.1 * total(exact).norm());
}

TEST(ForceModels, TheBodyFittedLoadWithEachNormal) {
  // At rest the residual method's nodal forces −R are the pressure on the deformed
  // outline (body_fitted_force.hpp); coupling.force = "large" keeps them, "small"
  // moves the pressure to the reference normal.
  const Rigid r;
  const int nv = r.mesh.num_vertices();
  const std::vector<int> open(r.outline.begin(), r.outline.end());
  std::vector<Point> x;
  Eigen::VectorXd p(static_cast<Eigen::Index>(open.size()));
  for (std::size_t k = 0; k < open.size(); ++k) {
    const int v = open[k];
    x.push_back(r.mesh.vertices[v] + Point(r.u[v], r.u[nv + v]));
    p[static_cast<Eigen::Index>(k)] = r.s.p[v];
  }
  const Eigen::Matrix2Xd minus_R = pressure_nodal_forces(x, p);
  const Eigen::VectorXd deformed =
      body_fitted_load(r.mesh, open, -minus_R, p, r.u, PressureNormal::deformed);
  const Eigen::VectorXd reference =
      body_fitted_load(r.mesh, open, -minus_R, p, r.u, PressureNormal::reference);
  const Point buoyancy = -0.3 * 0.03 * kF;
  // The open outline leaves out the left side's last segment, (0, H) → (0, 0):
  // add its share to compare totals with the closed body's.
  const Point a = x.back(), b = x.front(), e = b - a;
  const Point closing = -Point(e.y(), -e.x()) * (p[static_cast<Eigen::Index>(open.size()) - 1] + p[0]) / 2;
  EXPECT_LT((total(deformed) + closing - buoyancy).norm(), 1e-10 * buoyancy.norm());
  const Point A = r.mesh.vertices[open.back()], B = r.mesh.vertices[open.front()], E = B - A;
  const Point closing_ref = -Point(E.y(), -E.x()) * (p[static_cast<Eigen::Index>(open.size()) - 1] + p[0]) / 2;
  const Point turned = r.R.transpose() * buoyancy;
  EXPECT_LT((total(reference) + closing_ref - turned).norm(), 1e-10 * turned.norm());
}

}  // namespace
}  // namespace fsi::force_models_test
