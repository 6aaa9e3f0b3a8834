// The force on the structure (eq. 33) checked alone: for fluid fields given in
// closed form, FluidForce (P1 samples at deformed vertices × fixed matrices) must
// equal the integrals computed independently by quadrature of the composed fields.
// With v, p linear and u affine, ṽ = v∘φ and p̃ = p∘φ are exactly P1, so the two
// agree to round-off; for smooth nonlinear fields they differ by interpolation
// errors: the structure mesh's (the transfer's own, second order in hS) and the fixed
// background fluid mesh's (which does not shrink with hS); the two are measured apart.
#include <gtest/gtest.h>

#include "coupling/force_transfer.hpp"
#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::force_transfer_test {
namespace {

// μ_F, ε and f_F of eq. (33); a test isolates a term by zeroing the others (1/ε = 0
// with ε = ∞).
struct Coefficients {
  double mu = 0.0035, eps = 1e-5;
  Point f = Point(0.3, -981.0);
  FluidForce force(const Mesh& ref) const {
    return FluidForce(ref, mu, eps, [f = f](const Point&) { return f; });
  }
};

// The fluid fields on a background mesh covering the structure: P1 nodal values of
// the closed-form fields, bubbles zero.
// hF = 0.01 (as the paper's coarsest fluid mesh) divided by `refinement`.
struct ClosedFormFluid {
  Mesh mesh;
  std::function<Point(const Point&)> v;
  std::function<double(const Point&)> p;
  FluidSolution solution;
  std::unique_ptr<PointLocator> locator;
  ClosedFormFluid(std::function<Point(const Point&)> v_, std::function<double(const Point&)> p_,
                  int refinement = 1)
      : mesh(testing::structured_rectangle(0.5, 0.2, 50 * refinement, 20 * refinement)),
        v(std::move(v_)),
        p(std::move(p_)) {
    for (auto& x : mesh.vertices) x += Point(-0.1, -0.1);
    const int nv = mesh.num_vertices();
    solution.v1.resize(nv), solution.v2.resize(nv), solution.p.resize(nv);
    for (int i = 0; i < nv; ++i) {
      const Point vi = v(mesh.vertices[i]);
      solution.v1[i] = vi.x(), solution.v2[i] = vi.y(), solution.p[i] = p(mesh.vertices[i]);
    }
    solution.bubble = Eigen::Matrix2Xd::Zero(2, mesh.num_triangles());
    locator = std::make_unique<PointLocator>(mesh);
  }
};

// Independent evaluation: for every basis function w = φ_a e_c of the reference mesh,
// ∫ 2μ ε(ṽ):ε(w) − ∫ div(w) p̃ + (1/ε) ∫ ṽ·w − ∫ f_F·w by quadrature of the composed
// closed-form fields, with ∇ṽ by central differences of v∘φ (exact for linear v, u).
using VelocityFunction = std::function<Point(const Point&)>;
using PressureFunction = std::function<double(const Point&)>;

Eigen::VectorXd direct_force(const Mesh& ref, const Eigen::VectorXd& u, const VelocityFunction& v,
                             const PressureFunction& p, const Coefficients& k = {}) {
  const int nv = ref.num_vertices();
  const TriangleRule rule = triangle_rule(6);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(2 * nv);
  for (int t = 0; t < ref.num_triangles(); ++t) {
    const P1Triangle T(ref, t);
    const auto& tri = ref.triangles[t];
    // φ(X) = X + u(X) on this triangle (u is P1).
    auto phi = [&](const Point& X) {
      const Eigen::Vector3d l = T.barycentric(X);
      Point x = X;
      for (int a = 0; a < 3; ++a) x += l[a] * Point(u[tri[a]], u[nv + tri[a]]);
      return x;
    };
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const Point X = T.point(rule.lambda[q]);
      const double w = rule.w[q] * T.area, h = 1e-6;
      const Point v_t = v(phi(X));
      const double p_t = p(phi(X));
      Eigen::Matrix2d grad;  // ∇_X ṽ
      for (int d = 0; d < 2; ++d) {
        Point dX = Point::Zero();
        dX[d] = h;
        grad.col(d) = (v(phi(X + dX)) - v(phi(X - dX))) / (2 * h);
      }
      const Eigen::Matrix2d eps_v = 0.5 * (grad + grad.transpose());
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 2; ++c) {
          Eigen::Matrix2d grad_w = Eigen::Matrix2d::Zero();
          grad_w.row(c) = T.grad.row(a);
          const Eigen::Matrix2d eps_w = 0.5 * (grad_w + grad_w.transpose());
          const double phi_a = rule.lambda[q][a];
          F[dof(tri[a], c, nv)] +=
              w * (2 * k.mu * (eps_v.array() * eps_w.array()).sum() - grad_w.trace() * p_t +
                   v_t[c] * phi_a / k.eps - k.f[c] * phi_a);
        }
    }
  }
  return F;
}

Eigen::VectorXd affine_displacement(const Mesh& ref) {
  const int nv = ref.num_vertices();
  Eigen::VectorXd u(2 * nv);
  for (int i = 0; i < nv; ++i) {
    const Point& X = ref.vertices[i];
    u[i] = 0.002 + 0.01 * X.x() - 0.02 * X.y();
    u[nv + i] = -0.005 - 0.03 * X.x() + 0.01 * X.y();
  }
  return u;
}

TEST(ForceTransfer, EqualsTheIntegralsForLinearFieldsExactly) {
  const Mesh ref = generate_structure_mesh({0.3, 0.03, 0.16, 0.24, 0.015});
  const ClosedFormFluid fl([](const Point& x) { return Point(1.0 + 2.0 * x.x() - 3.0 * x.y(), -0.5 + x.x() + 4.0 * x.y()); },
                           [](const Point& x) { return 10.0 - 7.0 * x.x() + 2.0 * x.y(); });
  const Eigen::VectorXd u = affine_displacement(ref);
  const FluidForce force = Coefficients{}.force(ref);
  const FluidField field(*fl.locator, fl.solution);
  const Eigen::VectorXd ours = force(sample_at_deformed_vertices(field, ref, u), u);
  const Eigen::VectorXd direct = direct_force(ref, u, fl.v, fl.p);
  EXPECT_LT((ours - direct).norm(), 1e-7 * direct.norm());  // central differences: ~1e-9 relative
}

// coupling.force_sampling = m: the same integrals on the reference mesh cut into m²,
// restricted to its vertices; for linear fields and affine u still exact.
TEST(ForceTransfer, SampledOnARefinementStillEqualsTheIntegralsForLinearFields) {
  const Mesh ref = generate_structure_mesh({0.3, 0.03, 0.16, 0.24, 0.015});
  const ClosedFormFluid fl([](const Point& x) { return Point(1.0 + 2.0 * x.x() - 3.0 * x.y(), -0.5 + x.x() + 4.0 * x.y()); },
                           [](const Point& x) { return 10.0 - 7.0 * x.x() + 2.0 * x.y(); });
  const Eigen::VectorXd u = affine_displacement(ref);
  const Coefficients k;
  const FluidField field(*fl.locator, fl.solution);
  const Eigen::VectorXd direct = direct_force(ref, u, fl.v, fl.p);
  for (const ForceModel model : {ForceModel::small, ForceModel::large})
    for (int m : {2, 3}) {
      const FluidForce force(ref, k.mu, k.eps, [f = k.f](const Point&) { return f; }, model, m);
      ASSERT_EQ(force.sample_mesh().num_triangles(), m * m * ref.num_triangles());
      const Eigen::VectorXd ours =
          force(sample_at_deformed_vertices(field, force.sample_mesh(), force.to_samples(u)), u);
      if (model == ForceModel::small) {
        EXPECT_LT((ours - direct).norm(), 1e-7 * direct.norm()) << "m " << m;
      }
      const FluidForce once(ref, k.mu, k.eps, [f = k.f](const Point&) { return f; }, model, 1);
      EXPECT_LT((ours - once(sample_at_deformed_vertices(field, ref, u), u)).norm(), 1e-9 * direct.norm()) << "m " << m;
    }
}

// ṽ = v∘φ and p̃ = p∘φ at the deformed vertices, from the closed forms (no fluid mesh).
SampledFluid exact_samples(const Mesh& ref, const Eigen::VectorXd& u, const VelocityFunction& v,
                           const PressureFunction& p) {
  const int nv = ref.num_vertices();
  SampledFluid s{Eigen::VectorXd(2 * nv), Eigen::VectorXd(nv)};
  for (int i = 0; i < nv; ++i) {
    const Point x = ref.vertices[i] + Point(u[i], u[nv + i]);
    s.v[i] = v(x).x(), s.v[nv + i] = v(x).y(), s.p[i] = p(x);
  }
  return s;
}

// Loads are nodal: their action on a smooth test field (the L² pairing), relative.
double paired_error(const Mesh& ref, const Eigen::VectorXd& ours, const Eigen::VectorXd& exact) {
  const int nv = ref.num_vertices();
  Eigen::VectorXd test(2 * nv);
  for (int i = 0; i < nv; ++i) {
    test[i] = std::cos(3 * ref.vertices[i].x());
    test[nv + i] = std::sin(4 * ref.vertices[i].x() + ref.vertices[i].y());
  }
  return std::abs(test.dot(ours - exact)) / std::abs(test.dot(exact));
}

Point smooth_v(const Point& x) {
  return Point(std::sin(8 * x.x()) * std::cos(5 * x.y()), std::cos(6 * x.x() + 3 * x.y()));
}
double smooth_p(const Point& x) {
  return std::exp(2 * x.x()) * std::sin(9 * x.y());
}

Mesh beam(double h) {
  return generate_structure_mesh({0.3, 0.03, 0.16, 0.24, h});
}

// A Brinkman layer thinner than the structure's triangles (issue 27): v decays from 1
// to 0 over δ = hS/10 inside the beam's top. Sampled at the vertices only (m = 1), the
// penalty term's load misses the layer by a factor of several; sampling on the
// triangles cut into m² converges to the finely sampled load (m = 16) as m grows.
TEST(ForceTransfer, SamplingOnARefinementResolvesALayerThinnerThanTheMesh) {
  const double hS = 0.015, delta = hS / 10;
  const Mesh ref = beam(hS);
  const VelocityFunction layer = [&](const Point& x) { return Point(std::exp(-(0.03 - x.y()) / delta), 0.0); };
  const PressureFunction zero = [](const Point&) { return 0.0; };
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * ref.num_vertices());
  auto load = [&](int m) {
    const FluidForce force(ref, 0.0035, 1e-5, [](const Point&) { return Point(0, 0); }, ForceModel::small, m);
    return Eigen::VectorXd(force(exact_samples(force.sample_mesh(), force.to_samples(u), layer, zero), u));
  };
  const Eigen::VectorXd fine = load(16);
  // The total x load: ∫ v/ε ≈ L δ / ε (the layer's integral along the top).
  EXPECT_NEAR(fine.head(ref.num_vertices()).sum(), 0.3 * delta / 1e-5, 0.03 * 0.3 * delta / 1e-5);
  // Measured: 2.29, 0.89, 0.26, 0.056 for m = 1, 2, 4, 8: once the sub-triangles are
  // as thin as the layer (m ≥ 4 here), second order in hS/m.
  double error[4];
  const int ms[4] = {1, 2, 4, 8};
  for (int i = 0; i < 4; ++i) {
    error[i] = (load(ms[i]) - fine).norm() / fine.norm();
    std::printf("m %d: relative error %.3e\n", ms[i], error[i]);
  }
  EXPECT_GT(error[0], 1.0);  // the vertex samples see the layer only at the top's vertices
  EXPECT_GT(error[2] / error[3], 3.0);
  EXPECT_LT(error[3], 0.1);
}

// The observed order between successive meshes, h halved each time.
std::vector<double> observed_orders(const std::vector<double>& errors) {
  std::vector<double> orders;
  for (std::size_t k = 1; k < errors.size(); ++k)
    orders.push_back(std::log2(errors[k - 1] / errors[k]));
  return orders;
}

// The transfer alone: ṽ = v∘φ and p̃ = p∘φ from the closed forms at the deformed
// vertices. FluidForce pairs their P1 interpolants on the structure mesh with exact
// matrices (and an exact body force, f_F constant), so its error, paired with the
// smooth test field t, is that of P1 interpolation: (1/ε)∫(ṽ − Iṽ)·It and
// ∫ div(It)(p̃ − Ip̃) are O(hS²), and ∫ ε(ṽ − Iṽ):ε(It) is too (integrated by parts
// against the smooth t; the rest is O(hS)·O(hS)). Expected order 2.
//
// Each term alone (the penalty term, 1/ε = 1e5, would hide an error in the others),
// on structured meshes halved exactly, 2 to 16 cells through the thickness: measured
// 2.00 for the penalty and viscous terms, 2.05, 2.01, 2.00 for the pressure term;
// asserted within 2 ± 0.1. (On Gmsh's meshes the viscous and pressure terms' paired
// errors jump about, 0.1 to 4: their leading h² coefficient changes sign with the
// local mesh, so a single pairing cancels on some meshes.)
TEST(ForceTransfer, EachTermAloneConvergesAtSecondOrder) {
  const auto zero_v = [](const Point&) { return Point(0, 0); };
  const auto zero_p = [](const Point&) { return 0.0; };
  struct Term {
    const char* name;
    Coefficients k;
    VelocityFunction v;
    PressureFunction p;
  };
  const double none = INFINITY;  // ε = ∞: no penalty term
  const std::vector<Term> terms = {
      {"penalty", {0.0, 1e-5, Point(0, 0)}, smooth_v, zero_p},
      {"viscous", {0.0035, none, Point(0, 0)}, smooth_v, zero_p},
      {"pressure", {0.0, none, Point(0, 0)}, zero_v, smooth_p},
  };
  for (const Term& term : terms) {
    std::vector<double> errors;
    for (int n : {2, 4, 8, 16}) {
      const Mesh ref = testing::structured_rectangle(0.3, 0.03, 10 * n, n);
      const Eigen::VectorXd u = affine_displacement(ref);
      const Eigen::VectorXd ours = term.k.force(ref)(exact_samples(ref, u, term.v, term.p), u);
      errors.push_back(paired_error(ref, ours, direct_force(ref, u, term.v, term.p, term.k)));
    }
    const std::vector<double> orders = observed_orders(errors);
    for (std::size_t k = 0; k < orders.size(); ++k) {
      std::printf("transfer alone, %s term: error %.3e -> %.3e, order %.2f\n", term.name, errors[k],
                  errors[k + 1], orders[k]);
      EXPECT_NEAR(orders[k], 2.0, 0.1)
          << term.name << " term, between meshes " << k << " and " << k + 1;
    }
  }
}

// The whole force on the program's own beam meshes (the lattice generator's), hS =
// 0.015 → 0.001875: measured orders 1.94, 2.06, 2.00; asserted within 2 ± 0.25, as
// these meshes halve their element size only on average. (From hS = 0.03, whose two
// rows of triangles become three, not four, at 0.015: 1.36.)
TEST(ForceTransfer, TheTransferAloneConvergesAtSecondOrderOnTheBeamMeshes) {
  std::vector<double> errors;
  for (double h : {0.015, 0.0075, 0.00375, 0.001875}) {
    const Mesh ref = beam(h);
    const Eigen::VectorXd u = affine_displacement(ref);
    const Eigen::VectorXd ours =
        Coefficients{}.force(ref)(exact_samples(ref, u, smooth_v, smooth_p), u);
    errors.push_back(paired_error(ref, ours, direct_force(ref, u, smooth_v, smooth_p)));
  }
  const std::vector<double> orders = observed_orders(errors);
  for (std::size_t k = 0; k < orders.size(); ++k) {
    std::printf("transfer alone, whole force: error %.3e -> %.3e, order %.2f\n", errors[k],
                errors[k + 1], orders[k]);
    EXPECT_NEAR(orders[k], 2.0, 0.25) << "between meshes " << k << " and " << k + 1;
  }
}

// What the coupling sees: ṽ, p̃ sampled from the fluid's P1 field on a fixed
// background mesh. The error then has two parts: the transfer's, O(hS²) as above,
// and the background's interpolation error, which does not shrink with hS: the
// error of the background field's exact force (direct_force on v_h, p_h), E_bg. On
// hS = 0.001875: E_bg = 6.93e-4 for hF = 0.01 (the same to 3 digits for hS = 0.0075
// and 0.00375) and 1.74e-4 for hF = 0.005, order 2.00 in hF (P1 interpolation;
// asserted within 2 ± 0.1, the background being structured). The error through the
// background is E_bg plus the transfer's: |through − E_bg| = 1.77e-5 and 1.74e-5,
// the transfer alone's 1.745e-5 to 1%; asserted below 1.5 times it, while E_bg is
// 10–40 times larger (asserted > 5 times): the error levels off at E_bg.
TEST(ForceTransfer, ThroughTheBackgroundFieldTheErrorLevelsOffAtItsInterpolationError) {
  const Mesh ref = beam(0.001875);
  const Eigen::VectorXd u = affine_displacement(ref);
  const FluidForce force = Coefficients{}.force(ref);
  const Eigen::VectorXd exact = direct_force(ref, u, smooth_v, smooth_p);
  const double alone =
      paired_error(ref, force(exact_samples(ref, u, smooth_v, smooth_p), u), exact);
  std::vector<double> plateau;
  for (int refinement : {1, 2}) {
    const ClosedFormFluid fl(smooth_v, smooth_p, refinement);
    const FluidField field(*fl.locator, fl.solution);
    const double through =
        paired_error(ref, force(sample_at_deformed_vertices(field, ref, u), u), exact);
    const Eigen::VectorXd background_exactly = direct_force(
        ref, u, [&](const Point& x) { return field.at(x).v; },
        [&](const Point& x) { return field.at(x).p; });
    plateau.push_back(paired_error(ref, background_exactly, exact));
    std::printf(
        "hF = %.4f, hS = 0.001875: error through the background %.3e, of the background field "
        "itself "
        "%.3e, of the transfer alone %.3e\n",
        0.01 / refinement, through, plateau.back(), alone);
    EXPECT_LT(std::abs(through - plateau.back()), 1.5 * alone) << "hF = " << 0.01 / refinement;
    EXPECT_GT(plateau.back(), 5 * alone) << "hF = " << 0.01 / refinement;
  }
  const double order = observed_orders(plateau)[0];
  std::printf("background interpolation error: order %.2f in hF\n", order);
  EXPECT_NEAR(order, 2.0, 0.1);
}

TEST(ForceTransfer, SamplesOutsideTheFluidDomainAtTheNearestPoint) {
  const ClosedFormFluid fl([](const Point& x) { return Point(x.x(), x.y()); }, [](const Point& x) { return x.x(); });
  const FluidField field(*fl.locator, fl.solution);
  // The background covers (−0.1, 0.4) × (−0.1, 0.1): (0.5, 0.05) is outside; nearest (0.4, 0.05).
  const FluidValue val = field.at(Point(0.5, 0.05));
  EXPECT_NEAR(val.v.x(), 0.4, 1e-12);
  EXPECT_NEAR(val.v.y(), 0.05, 1e-12);
  EXPECT_NEAR(val.p, 0.4, 1e-12);
}

}  // namespace
}  // namespace fsi::force_transfer_test
