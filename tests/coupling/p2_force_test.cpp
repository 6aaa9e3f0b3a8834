// The fluid force on a P2 structure (structure.element = "P2", issue 14): eq. (33)'s
// small form and its pull-back on the P2 space, checked against
//   - the P1 force, for fields and test functions P1 holds (both exact: equal to round-off);
//   - a brute-force integral of the closed-form integrand with the P2 basis written out
//     here (quadratic fields, all integrands polynomial: equal to round-off);
//   - the small form assembled on the displaced mesh, for an affine deformation (the
//     change of variables is then exact: equal to round-off);
//   - the small form as u → 0 (first order in u);
//   - under a curved φ, the direct integral on the deformed body (namespace curved).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "coupling/force_transfer.hpp"
#include "fem/p2.hpp"
#include "fem/quadrature.hpp"
#include "support/structured_mesh.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi::p2_force_test {
namespace {

constexpr double kMu = 0.7, kEps = 0.5;  // all terms of comparable size
Point affine_f(const Point& x) {
  return Point(0.3 + 2 * x.x() - x.y(), -1.0 + x.x() + 0.5 * x.y());
}

// (0, 1) × (0, 0.5), 4 × 2 cells, interior vertices moved off the grid so that no
// triangle is right-angled or like another.
Mesh skewed_mesh() {
  Mesh mesh = testing::structured_rectangle(1.0, 0.5, 4, 2);
  for (Point& x : mesh.vertices)
    if (x.x() > 0 && x.x() < 1 && x.y() > 0 && x.y() < 0.5)
      x += Point(0.07 * std::sin(9 * x.x()), 0.04 * std::cos(7 * x.x()));
  return mesh;
}

// Quadratic closed forms (P2 holds them exactly) and their gradients.
Point quadratic_v(const Point& X) {
  const double x = X.x(), y = X.y();
  return Point(1 + 2 * x - y + 3 * x * x - x * y + 0.5 * y * y,
               -0.5 + x + 4 * y - x * x + 2 * x * y - y * y);
}
Eigen::Matrix2d quadratic_v_gradient(const Point& X) {  // row c = ∇v_c
  const double x = X.x(), y = X.y();
  Eigen::Matrix2d g;
  g << 2 + 6 * x - y, -1 - x + y, 1 - 2 * x + 2 * y, 4 + 2 * x - 2 * y;
  return g;
}
double quadratic_p(const Point& X) {
  const double x = X.x(), y = X.y();
  return 2 - x + 3 * y + x * x - 2 * x * y + 4 * y * y;
}
// A non-affine displacement: a bend and a stretch.
Point quadratic_u(const Point& X) {
  const double x = X.x(), y = X.y();
  return Point(0.1 * x * x - 0.2 * y + 0.05 * x * y, 0.15 * x * y + 0.1 * y * y - 0.08 * x * x);
}

// Nodal values (the P2 interpolant) of closed forms on `nodes`.
Eigen::VectorXd vector_nodal(const std::vector<Point>& nodes,
                             const std::function<Point(const Point&)>& f) {
  const int n = static_cast<int>(nodes.size());
  Eigen::VectorXd out(2 * n);
  for (int i = 0; i < n; ++i) out[i] = f(nodes[i]).x(), out[n + i] = f(nodes[i]).y();
  return out;
}
SampledFluid sampled(const std::vector<Point>& nodes, const std::function<Point(const Point&)>& v,
                     const std::function<double(const Point&)>& p) {
  SampledFluid s{vector_nodal(nodes, v), Eigen::VectorXd(nodes.size())};
  for (std::size_t i = 0; i < nodes.size(); ++i) s.p[i] = p(nodes[i]);
  return s;
}

double relative_max(const Eigen::VectorXd& got, const Eigen::VectorXd& expected) {
  return (got - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
}

// Pᵀ load: the P2 load tested against the P2 interpolants of the P1 basis functions
// (1 at their vertex, ½ at the midpoints of its edges), i.e. Σ_i load_i w(node_i) for
// every P1 basis w.
Eigen::VectorXd restricted_to_p1(const P2Space& space, const Eigen::VectorXd& load) {
  const int nv = space.mesh().num_vertices(), n = space.num_nodes();
  Eigen::VectorXd out(2 * nv);
  for (int c = 0; c < 2; ++c) out.segment(c * nv, nv) = load.segment(c * n, nv);
  std::vector<bool> seen(n, false);
  for (int t = 0; t < space.mesh().num_triangles(); ++t) {
    const auto& e = space.element(t);
    for (int k = 0; k < 3; ++k) {
      const int m = e[3 + k];
      if (seen[m]) continue;
      seen[m] = true;
      for (int c = 0; c < 2; ++c)
        for (int end : {e[k], e[(k + 1) % 3]}) out[c * nv + end] += 0.5 * load[c * n + m];
    }
  }
  return out;
}

TEST(P2Force, EqualsTheP1ForceOnP1FieldsAndTestFunctions) {
  const Mesh mesh = skewed_mesh();
  const P2Space space(mesh);
  const auto v = [](const Point& x) {
    return Point(1 + 2 * x.x() - 3 * x.y(), -0.5 + x.x() + 4 * x.y());
  };
  const auto p = [](const Point& x) { return 10 - 7 * x.x() + 2 * x.y(); };
  const Eigen::VectorXd p1 = FluidForce(mesh, kMu, kEps, affine_f)(
      sampled(mesh.vertices, v, p), Eigen::VectorXd::Zero(2 * mesh.num_vertices()));
  const Eigen::VectorXd p2 = FluidForce(space, kMu, kEps, affine_f)(
      sampled(space.nodes(), v, p), Eigen::VectorXd::Zero(2 * space.num_nodes()));
  const double gap = relative_max(restricted_to_p1(space, p2), p1);
  std::printf("P2 vs P1 force on P1 data: max relative gap %.2e\n", gap);
  EXPECT_LT(gap, 1e-13);  // round-off of sums of O(50) terms
  // And for the random P1 test function the issue names, w_v = sin(3v + 1) per dof.
  Eigen::VectorXd w(2 * mesh.num_vertices());
  for (int i = 0; i < w.size(); ++i) w[i] = std::sin(3.0 * i + 1);
  EXPECT_NEAR(w.dot(restricted_to_p1(space, p2)), w.dot(p1), 1e-13 * p1.cwiseAbs().sum());
}

// The test's own P2 basis on triangle (x0, x1, x2): barycentric coordinates λ and
// their gradients from the triangle's Jacobian, N_a = λ_a(2λ_a − 1), N_{3+k} = 4λ_kλ_{k+1}.
struct OwnBasis {
  double N[6];
  Eigen::RowVector2d grad[6];
};
OwnBasis own_basis(const Point (&x)[3], const Point& X) {
  Eigen::Matrix2d A;
  A.col(0) = x[1] - x[0], A.col(1) = x[2] - x[0];
  const Eigen::Matrix2d Ainv = A.inverse();
  const Eigen::Vector2d l12 = Ainv * (X - x[0]);
  const double l[3] = {1 - l12[0] - l12[1], l12[0], l12[1]};
  const Eigen::RowVector2d g[3] = {-Ainv.row(0) - Ainv.row(1), Ainv.row(0), Ainv.row(1)};
  OwnBasis b;
  for (int a = 0; a < 3; ++a) b.N[a] = l[a] * (2 * l[a] - 1), b.grad[a] = (4 * l[a] - 1) * g[a];
  for (int k = 0; k < 3; ++k) {
    const int m = (k + 1) % 3;
    b.N[3 + k] = 4 * l[k] * l[m], b.grad[3 + k] = 4 * (l[m] * g[k] + l[k] * g[m]);
  }
  return b;
}

// ∫ 2μ ε(v):ε(w) − ∫ p div w + (1/ε) ∫ v·w − ∫ f(X + u(X))·w for w = N_a e_c, from the
// closed forms at the points of a degree-10 rule (the integrands' degree is at most 4).
Eigen::VectorXd brute_force_small(const P2Space& space) {
  const Mesh& mesh = space.mesh();
  const int n = space.num_nodes();
  const TriangleRule rule = triangle_rule(10);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(2 * n);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Point x[3] = {mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
    const double area = 0.5 * std::abs((x[1] - x[0]).x() * (x[2] - x[0]).y() -
                                       (x[1] - x[0]).y() * (x[2] - x[0]).x());
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const Point X =
          rule.lambda[q][0] * x[0] + rule.lambda[q][1] * x[1] + rule.lambda[q][2] * x[2];
      const OwnBasis b = own_basis(x, X);
      const Eigen::Matrix2d gv = quadratic_v_gradient(X), eps_v = 0.5 * (gv + gv.transpose());
      const Point v = quadratic_v(X), f = affine_f(X + quadratic_u(X));
      for (int a = 0; a < 6; ++a)
        for (int c = 0; c < 2; ++c) {
          Eigen::Matrix2d gw = Eigen::Matrix2d::Zero();
          gw.row(c) = b.grad[a];
          const double viscous =
              2 * kMu * (eps_v.array() * (0.5 * (gw + gw.transpose())).array()).sum();
          load[c * n + space.element(t)[a]] +=
              rule.w[q] * area *
              (viscous - gw.trace() * quadratic_p(X) + (v[c] / kEps - f[c]) * b.N[a]);
        }
    }
  }
  return load;
}

TEST(P2Force, SmallFormEqualsABruteForceIntegralForQuadraticFields) {
  const Mesh mesh = skewed_mesh();
  const P2Space space(mesh);
  const Eigen::VectorXd ours = FluidForce(space, kMu, kEps, affine_f)(
      sampled(space.nodes(), quadratic_v, quadratic_p), vector_nodal(space.nodes(), quadratic_u));
  const double gap = relative_max(ours, brute_force_small(space));
  std::printf("P2 small force vs brute force, quadratic fields: max relative gap %.2e\n", gap);
  EXPECT_LT(gap, 1e-10);
}

// u(X) = (G − I) X + b: on each triangle F = G, and the nodes (vertices, midpoints) map
// to the displaced mesh's nodes in the same order.
TEST(P2Force, LargeFormIsTheSmallFormOnTheDisplacedMeshForAnAffineDeformation) {
  const Mesh mesh = skewed_mesh();
  const P2Space space(mesh);
  Eigen::Matrix2d G;
  G << 1.3, 0.4, -0.2, 0.8;  // stretch and shear, det 1.12
  const Point shift(0.05, -0.1);
  const auto u_of = [&](const Point& X) { return Point(G * X + shift - X); };
  const Eigen::VectorXd u = vector_nodal(space.nodes(), u_of);
  const int nv = mesh.num_vertices(), n = space.num_nodes();
  const Mesh deformed = displaced(mesh, u.segment(0, nv), u.segment(n, nv));
  const P2Space deformed_space(deformed);
  ASSERT_EQ(deformed_space.num_nodes(), n);
  for (int i = 0; i < n; ++i)
    ASSERT_LT((deformed_space.nodes()[i] - (G * space.nodes()[i] + shift)).norm(), 1e-14);

  const SampledFluid s =
      sampled(space.nodes(), quadratic_v, quadratic_p);  // ṽ, p̃ at the nodes: any values
  const Eigen::VectorXd large = FluidForce(space, kMu, kEps, affine_f, ForceModel::large)(s, u);
  const Eigen::VectorXd direct =
      FluidForce(deformed_space, kMu, kEps, affine_f)(s, Eigen::VectorXd::Zero(2 * n));
  const double gap = relative_max(large, direct);
  std::printf("P2 large form vs small form on the displaced mesh: max relative gap %.2e\n", gap);
  EXPECT_LT(gap, 1e-11);
  // The deformation is large: the small form on the reference misses by far more.
  const Eigen::VectorXd small = FluidForce(space, kMu, kEps, affine_f)(s, u);
  EXPECT_GT(relative_max(small, direct), 1e-2);
}

// ‖large(t u) − small(t u)‖ / ‖small‖ is O(t): halving t halves it (u non-affine,
// so F varies in each triangle and the degree-6 rule is not exact: its error is far
// below the gap measured).
TEST(P2Force, LargeFormTendsToTheSmallFormAtFirstOrderInTheDisplacement) {
  const Mesh mesh = skewed_mesh();
  const P2Space space(mesh);
  const SampledFluid s = sampled(space.nodes(), quadratic_v, quadratic_p);
  const FluidForce large(space, kMu, kEps, affine_f, ForceModel::large);
  const FluidForce small(space, kMu, kEps, affine_f);
  const Eigen::VectorXd u = vector_nodal(space.nodes(), quadratic_u);
  double last = 0;
  for (double t : {1e-2, 5e-3, 2.5e-3, 1.25e-3}) {
    const Eigen::VectorXd reference = small(s, t * u);
    const double gap = (large(s, t * u) - reference).norm() / reference.norm();
    if (last > 0) {
      std::printf("P2 large - small at t = %.2e: %.3e, ratio to the previous t %.4f\n", t, gap,
                  last / gap);
      EXPECT_NEAR(last / gap, 2.0, 0.05) << "t = " << t;
    }
    last = gap;
  }
}

TEST(P2Force, ASampleOfTheWrongSizeThrows) {
  const Mesh mesh = skewed_mesh();
  const P2Space space(mesh);
  const int n = space.num_nodes(), nv = mesh.num_vertices();
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * n);
  for (ForceModel model : {ForceModel::small, ForceModel::large}) {
    const FluidForce p2(space, kMu, kEps, affine_f, model);
    EXPECT_NO_THROW(p2(SampledFluid{Eigen::VectorXd::Zero(2 * n), Eigen::VectorXd::Zero(n)}, u));
    // P1-sized samples, a short p, a P1-sized u.
    EXPECT_THROW(p2(SampledFluid{Eigen::VectorXd::Zero(2 * nv), Eigen::VectorXd::Zero(nv)}, u),
                 std::invalid_argument);
    EXPECT_THROW(p2(SampledFluid{Eigen::VectorXd::Zero(2 * n), Eigen::VectorXd::Zero(n - 1)}, u),
                 std::invalid_argument);
    EXPECT_THROW(p2(SampledFluid{Eigen::VectorXd::Zero(2 * n), Eigen::VectorXd::Zero(n)},
                    Eigen::VectorXd::Zero(2 * nv)),
                 std::invalid_argument);
    const FluidForce p1(mesh, kMu, kEps, affine_f, model);
    EXPECT_THROW(p1(SampledFluid{Eigen::VectorXd::Zero(2 * n), Eigen::VectorXd::Zero(n)},
                    Eigen::VectorXd::Zero(2 * nv)),
                 std::invalid_argument);
  }
}

// A curved, non-affine φ (a bend and a shear, far beyond small displacements): "large"
// against the small form's integrand summed on a fine straight-sided subdivision of
// the deformed elements, the direct integral on φ(Ω) with its geometry error
// O(h_sub²): the two converge at that order.
namespace curved {

constexpr double kMu = 0.0035, kEps = 1e-3;
const VectorField kF = [](const Point& x) { return Point(0.3 + x.y(), -9.81e3 + 50 * x.x()); };

// Fluid fields at the given points (values chosen smooth and non-polynomial).
SampledFluid fields_at(const std::vector<Point>& points) {
  const int n = static_cast<int>(points.size());
  SampledFluid f{Eigen::VectorXd(2 * n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const Point& X = points[i];
    f.v[i] = 0.02 * std::sin(9 * X.x()) + 0.01 * X.y();
    f.v[n + i] = -0.015 * std::cos(7 * X.y() + X.x());
    f.p[i] = 120 * std::cos(5 * X.x()) - 300 * X.y();
  }
  return f;
}

// A bend and a shear: φ(X) = X + s·d(X), sampled at the nodes.
Point bend(const Point& X, double s) {
  const double R = 0.25, a = X.x() / R, Y = X.y();
  const Point bent((R + Y) * std::sin(a), (R + Y) * std::cos(a) - R);
  return s * (bent - X + Point(0.4 * Y, 0.1 * X.x() * X.x()));
}

Eigen::VectorXd nodal(const std::vector<Point>& nodes, const std::function<Point(const Point&)>& d) {
  const int n = static_cast<int>(nodes.size());
  Eigen::VectorXd u(2 * n);
  for (int i = 0; i < n; ++i) {
    const Point x = d(nodes[i]);
    u[i] = x.x(), u[n + i] = x.y();
  }
  return u;
}

// The direct integral on φ(Ω): each element cut into k² sub-triangles, their vertices
// mapped by the P2 φ, and on each straight deformed piece the small form's integrand
// σ(ṽ):∇_x w + ṽ·w/ε − f·w with ∇_x = ∇_X · (the piece's affine map)⁻¹.
Eigen::VectorXd direct_on_deformed(const P2Space& space, const SampledFluid& s, const Eigen::VectorXd& u, int k) {
  const int n = space.num_nodes();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(2 * n);
  const TriangleRule rule = triangle_rule(4);
  for (int t = 0; t < space.mesh().num_triangles(); ++t) {
    const P1Triangle T(space.mesh(), t);
    const auto& nodes = space.element(t);
    auto phi = [&](const Eigen::Vector3d& l) {
      const P2Values v = p2_values(T, l);
      Point x = T.point(l);
      for (int a = 0; a < 6; ++a) x += v.N[a] * Point(u[nodes[a]], u[n + nodes[a]]);
      return x;
    };
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j)
        for (int up = 0; up < (i + j + 1 < k ? 2 : 1); ++up) {
          // The sub-triangle's barycentric corners (λ1, λ2) on the k-grid.
          std::array<Eigen::Vector3d, 3> c;
          const double h = 1.0 / k;
          auto bary = [&](double a, double b) { return Eigen::Vector3d(1 - a - b, a, b); };
          if (!up) c = {bary(i * h, j * h), bary((i + 1) * h, j * h), bary(i * h, (j + 1) * h)};
          else c = {bary((i + 1) * h, j * h), bary((i + 1) * h, (j + 1) * h), bary(i * h, (j + 1) * h)};
          Point X[3], x[3];
          for (int m = 0; m < 3; ++m) X[m] = T.point(c[m]), x[m] = phi(c[m]);
          Matrix2 dX, dx;
          dX << X[1] - X[0], X[2] - X[0];
          dx << x[1] - x[0], x[2] - x[0];
          const Matrix2 A = dx * dX.inverse();  // the piece's dx/dX
          const double area = 0.5 * std::abs(dx.determinant());
          for (std::size_t q = 0; q < rule.w.size(); ++q) {
            const Eigen::Vector3d l = c[0] * rule.lambda[q][0] + c[1] * rule.lambda[q][1] + c[2] * rule.lambda[q][2];
            const P2Values v = p2_values(T, l);
            const Eigen::Matrix<double, 6, 2> grad_x = v.grad * A.inverse();
            Matrix2 gv = Matrix2::Zero();
            Point vv(0, 0);
            double p = 0;
            for (int a = 0; a < 6; ++a) {
              for (int cc = 0; cc < 2; ++cc) gv.row(cc) += s.v[dof(nodes[a], cc, n)] * grad_x.row(a);
              vv += v.N[a] * Point(s.v[nodes[a]], s.v[n + nodes[a]]);
              p += v.N[a] * s.p[nodes[a]];
            }
            const Matrix2 sigma = -p * Matrix2::Identity() + kMu * (gv + gv.transpose());
            const Point xq = x[0] * rule.lambda[q][0] + x[1] * rule.lambda[q][1] + x[2] * rule.lambda[q][2];
            const Point body = vv / kEps - kF(xq);
            const double dA = rule.w[q] * area;
            for (int a = 0; a < 6; ++a)
              for (int cc = 0; cc < 2; ++cc)
                load[dof(nodes[a], cc, n)] += dA * (sigma.row(cc).dot(grad_x.row(a)) + body[cc] * v.N[a]);
          }
        }
  }
  return load;
}

TEST(P2Force, LargeUnderACurvedDeformationIsTheDirectIntegralOnTheDeformedBody) {
  const Mesh mesh = testing::structured_rectangle(0.3, 0.03, 6, 2);
  const P2Space space(mesh);
  const Eigen::VectorXd u = nodal(space.nodes(), [](const Point& X) { return bend(X, 1.0); });
  const SampledFluid s = fields_at(space.nodes());
  const Eigen::VectorXd large = FluidForce(space, kMu, kEps, kF, ForceModel::large)(s, u);
  double previous = 0;
  for (int k : {8, 16, 32}) {
    const double e = (direct_on_deformed(space, s, u, k) - large).cwiseAbs().maxCoeff() / large.cwiseAbs().maxCoeff();
    std::printf("k %2d: relative difference %.3e\n", k, e);
    if (previous > 0) {
      EXPECT_GT(previous / e, 3.0) << "not the subdivision's second order, k = " << k;
    }
    previous = e;
  }
  EXPECT_LT(previous, 1e-4);
}

}  // namespace curved

}  // namespace
}  // namespace fsi::p2_force_test
