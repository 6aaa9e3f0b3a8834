// The weak contact rows C_S, c_lb (SPEC §2) against closed-form integrals, and a
// contact problem with a known answer: a block resting on a flat floor under its
// own weight.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "qp/active_set_solver.hpp"
#include "qp/ipopt_solver.hpp"
#include "solid/contact_solver.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::contact_test {
namespace {

// Closed forms on the disk's arc, t = x − x0:
//   ∫ sqrt(r² − t²) dt = ½(t sqrt(r² − t²) + r² asin(t/r)),  ∫ t sqrt(r² − t²) dt = −(r² − t²)^{3/2}/3.
struct ArcIntegrals {
  double x0, y0, r;
  double F(double x) const {
    const double t = x - x0;
    return 0.5 * (t * std::sqrt(r * r - t * t) + r * r * std::asin(t / r));
  }
  double G(double x) const {
    const double t = x - x0;
    return -std::pow(r * r - t * t, 1.5) / 3.0;
  }
  double psi(double x) const { return y0 + std::sqrt(r * r - (x - x0) * (x - x0)); }
  // ∫_a^b ψ(x) φ(x) dx for the hat φ that is 1 at `peak` and 0 at the other end.
  double psi_times_hat(double a, double b, double peak) const {
    const double other = peak == a ? b : a, len = b - a;
    // φ(x) = (x − other)/(peak − other) = ((x − x0) + (x0 − other))/(peak − other)
    const double moment = (G(b) - G(a)) + (x0 - other) * (F(b) - F(a));
    return (y0 * 0.5 * len) + moment / (peak - other);
  }
  // ∫_a^b ψ'(x) φ(x) dx = [ψ φ]_a^b − φ' ∫_a^b ψ, by parts.
  double dpsi_times_hat(double a, double b, double peak) const {
    const double other = peak == a ? b : a;
    const double slope = 1.0 / (peak - other);
    return psi(peak) * 1.0 * (peak == b ? 1 : -1) - slope * (y0 * (b - a) + F(b) - F(a));
  }
};

// The arc's ψ' steepens towards the ends of Γ_C, so Gauss quadrature is least
// accurate on the end edges: 7e-10 relative with the default 5 points, below 1e-13
// with 10. A wrong formula would be off by O(1); quadrature alone by these amounts.
class ContactRowsQuadrature : public ::testing::TestWithParam<std::pair<int, double>> {};

TEST_P(ContactRowsQuadrature, MatchClosedFormIntegralsOnTheArc) {
  const auto [points, rel_tol] = GetParam();
  const double x0 = 0.055, y0 = -0.012, r = 0.005, gamma = 0.8;
  const Mesh mesh = generate_structure_mesh({0.06, 0.005, x0 - gamma * r, x0 + gamma * r, 0.0007});
  const DiskFoundation psi(x0, y0, r);
  const ContactConstraint cc = assemble_contact(mesh, mesh.label("Gamma_C"), psi, points);
  const ArcIntegrals exact{x0, y0, r};
  const int nv = mesh.num_vertices();
  Eigen::VectorXd e1 = Eigen::VectorXd::Zero(2 * nv), e2 = Eigen::VectorXd::Zero(2 * nv);
  e1.head(nv).setOnes();
  e2.tail(nv).setOnes();
  const Eigen::VectorXd C_e1 = cc.C_S * e1, C_e2 = cc.C_S * e2;
  ASSERT_GT(cc.row_vertex.size(), 8u);
  // ψ' changes sign mid-arc: measure errors against the row values' size.
  const double dpsi_scale = C_e1.lpNorm<Eigen::Infinity>(), psi_scale = cc.c_lb.lpNorm<Eigen::Infinity>();
  for (std::size_t i = 0; i < cc.row_vertex.size(); ++i) {
    const int v = cc.row_vertex[i];
    const double xv = mesh.vertices[v].x();
    double lump = 0, dpsi = 0, psi_int = 0;
    for (const auto& e : mesh.edges_on(mesh.label("Gamma_C"))) {
      if (e.v[0] != v && e.v[1] != v) continue;
      const double xa = std::min(mesh.vertices[e.v[0]].x(), mesh.vertices[e.v[1]].x());
      const double xb = std::max(mesh.vertices[e.v[0]].x(), mesh.vertices[e.v[1]].x());
      lump += 0.5 * (xb - xa);
      dpsi += exact.dpsi_times_hat(xa, xb, xv);
      psi_int += exact.psi_times_hat(xa, xb, xv);
    }
    // Row of C_S applied to u = (0,1): ∫ φ_i; to u = (1,0): −∫ ψ' φ_i; c_lb = ∫ (ψ − 0) φ_i.
    EXPECT_NEAR(C_e2[i], lump, 1e-13 * lump);
    EXPECT_NEAR(C_e1[i], -dpsi, rel_tol * dpsi_scale);
    EXPECT_NEAR(cc.c_lb[i], psi_int, rel_tol * psi_scale);
  }
}

INSTANTIATE_TEST_SUITE_P(GaussPoints, ContactRowsQuadrature,
                         ::testing::Values(std::make_pair(5, 1e-9), std::make_pair(10, 1e-13)));

TEST(ContactRows, OnlyVerticesStrictlyInsideGammaCCarryARow) {
  const Mesh mesh = generate_structure_mesh({0.06, 0.005, 0.051, 0.059, 0.001});
  const ContactConstraint cc = assemble_contact(mesh, mesh.label("Gamma_C"), DiskFoundation(0.055, -0.012, 0.005));
  const std::vector<int> on_gc = mesh.vertices_on(mesh.label("Gamma_C"));
  EXPECT_EQ(cc.row_vertex.size() + 2, on_gc.size());
  for (int v : cc.row_vertex) {
    EXPECT_GT(mesh.vertices[v].x(), 0.051 + 1e-12);
    EXPECT_LT(mesh.vertices[v].x(), 0.059 - 1e-12);
  }
}

// Block (0,L)×(0,H) on the floor ψ = 0 under its weight ρg, rollers (u1 = 0) on both
// sides. Exact: u1 = 0, u2 = ρg(y²/2 − H y)/(λ + 2μ), σ22 = ρg(y − H): a uniform
// contact pressure P = ρgH, the weight per unit length.
// The bottom corners carry no contact row (rows sit strictly inside Γ_C), so they
// are held at the floor by u2 = 0, which the exact solution satisfies. On a
// union-jack mesh every cell is identical and mirror-symmetric, so the discrete
// solution is exactly x-invariant: every interior bottom node carries the same
// contact force R and each corner R/2; equilibrium (total = weight) then gives
// R = P Δx exactly, the nodal form of a uniform pressure P. The displacement matches
// the exact one to the P1 error, O(h²).
class BlockOnFloor : public ::testing::TestWithParam<std::string> {};

TEST_P(BlockOnFloor, CarriesItsWeightAsAUniformPressure) {
  const double L = 0.2, H = 0.05, rho_g = 1.0e4;
  const int nx = 40, ny = 10;
  const Mesh mesh = testing::structured_rectangle(L, H, nx, ny, /*union_jack=*/true);
  const int nv = mesh.num_vertices();
  const Lame lame = Lame::from_young_poisson(3e5, 0.3);
  std::vector<int> fixed;
  for (const char* side : {"left", "right"})
    for (int v : mesh.vertices_on(mesh.label(side))) fixed.push_back(dof(v, 0, nv));
  fixed.push_back(dof(0, 1, nv));
  fixed.push_back(dof(nx, 1, nv));
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());

  std::unique_ptr<QpSolver> qp;
  if (GetParam() == "ipopt") {
    qp = std::make_unique<IpoptSolver>();
  } else {
    qp = std::make_unique<ActiveSetSolver>();
  }
  const FlatFoundation floor(0.0);
  ElasticContactSolver solver(mesh, lame, floor, mesh.label("bottom"), fixed, *qp);
  const Eigen::VectorXd b = assemble_volume_load(mesh, [&](const Point&) { return Point(0, -rho_g); });
  const ContactSolution s = solver.solve(b);

  const double P = rho_g * H, k = lame.lambda + 2 * lame.mu, u_scale = rho_g * H * H / k;
  const double tol = GetParam() == "ipopt" ? 1e-8 : 1e-10;  // IPOPT stops at tol 1e-14 (scaled)
  EXPECT_EQ(s.qp.active_count(), nx - 1);
  // x-invariance (exact up to the solver's accuracy) and the P1 error in y.
  const double h2 = (H / ny) * (H / ny) / (H * H);
  for (int v = 0; v < nv; ++v) {
    const Point& X = mesh.vertices[v];
    const double u2 = rho_g * (0.5 * X.y() * X.y() - H * X.y()) / k;
    EXPECT_NEAR(s.u[dof(v, 1, nv)], u2, h2 * u_scale) << "vertex " << v;
    EXPECT_NEAR(s.u[dof(v, 0, nv)], 0.0, tol * u_scale) << "vertex " << v;
    for (int w = 0; w < nv; ++w) {  // same height, same displacement
      if (std::abs(mesh.vertices[w].y() - X.y()) < 1e-12 * H) {
        EXPECT_NEAR(s.u[dof(w, 1, nv)], s.u[dof(v, 1, nv)], tol * u_scale);
      }
    }
  }
  // Nodal contact force Cᵀα on each interior bottom node = P × (its share of length).
  const Eigen::VectorXd force = solver.contact().C_S.transpose() * s.qp.alpha;
  for (int i = 1; i < nx; ++i) EXPECT_NEAR(force[dof(i, 1, nv)], P * L / nx, tol * P * L / nx);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, BlockOnFloor, ::testing::Values("active-set", "ipopt"));

// Without the corner supports nothing but the floor stops a vertical rigid motion:
// A_S is singular on the free dofs. The solver must refuse, not return garbage
// (CHOLMOD factorises this singular matrix without complaint).
TEST(BlockOnFloor, IsRejectedWhenNothingPreventsRigidMotion) {
  const Mesh mesh = testing::structured_rectangle(0.2, 0.05, 40, 10);
  const int nv = mesh.num_vertices();
  std::vector<int> fixed;
  for (const char* side : {"left", "right"})
    for (int v : mesh.vertices_on(mesh.label(side))) fixed.push_back(dof(v, 0, nv));
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  ActiveSetSolver qp;
  EXPECT_THROW(ElasticContactSolver(mesh, Lame::from_young_poisson(3e5, 0.3), FlatFoundation(0.0),
                                    mesh.label("bottom"), fixed, qp),
               std::invalid_argument);
  // One more fixed vertical dof removes the last rigid motion.
  fixed.push_back(dof(0, 1, nv));
  EXPECT_NO_THROW(ElasticContactSolver(mesh, Lame::from_young_poisson(3e5, 0.3), FlatFoundation(0.0),
                                       mesh.label("bottom"), fixed, qp));
}

}  // namespace
}  // namespace fsi::contact_test
