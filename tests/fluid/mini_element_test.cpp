// The mini element's closed-form integrals against quadrature, and static
// condensation against solving the uncondensed 11×11 element system.
#include "fluid/mini_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "fem/quadrature.hpp"

namespace fsi::mini_element_test {
namespace {

const P1Triangle kT(Point(0.1, -0.2), Point(0.7, 0.05), Point(0.25, 0.6));

TEST(MiniElement, ClosedFormIntegralsMatchQuadrature) {
  const TriangleRule rule = triangle_rule(8);  // exact for b² (degree 6)
  double b = 0, bb = 0;
  Eigen::Vector3d lb = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ll = Eigen::Matrix3d::Zero();
  Eigen::Matrix2d gg = Eigen::Matrix2d::Zero();
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Eigen::Vector3d& l = rule.lambda[q];
    const double w = rule.w[q] * kT.area, bq = bubble_value(l);
    b += w * bq;
    bb += w * bq * bq;
    lb += w * bq * l;
    ll += w * l * l.transpose();
    const Eigen::Vector2d g = bubble_gradient(kT, l);
    gg += w * g * g.transpose();
  }
  EXPECT_NEAR(b, bubble::bubble_integral(kT.area), 1e-15);
  EXPECT_NEAR(bb, bubble::bubble_squared(kT.area), 1e-16);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lb[a], bubble::p1_times_bubble(kT.area), 1e-16);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ll(a, c), bubble::mass_p1(kT.area, a, c), 1e-15);
  }
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(gg(c, d), bubble::grad_grad(kT, c, d), 1e-12);
}

TEST(MiniElement, BubbleGradientMatchesFiniteDifferences) {
  const Point x = kT.point(Eigen::Vector3d(0.2, 0.5, 0.3));
  const double h = 1e-6;
  const Eigen::Vector2d g = bubble_gradient(kT, kT.barycentric(x));
  for (int c = 0; c < 2; ++c) {
    Point dx = Point::Zero();
    dx[c] = h;
    const double fd = (bubble_value(kT.barycentric(x + dx)) - bubble_value(kT.barycentric(x - dx))) / (2 * h);
    EXPECT_NEAR(g[c], fd, 1e-8);
  }
}

// The 11×11 element system on [v1(3), v2(3), p(3), β1, β2], assembled entry by
// entry from quadrature of the weak form, not from the closed forms.
Eigen::MatrixXd uncondensed_by_quadrature(const P1Triangle& T, double mu, double kappa) {
  const TriangleRule rule = triangle_rule(8);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(11, 11);
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Eigen::Vector3d& l = rule.lambda[q];
    const double w = rule.w[q] * T.area;
    // velocity basis functions: value (2-vector) and gradient (2×2) per local dof
    std::vector<Eigen::Vector2d> val(11, Eigen::Vector2d::Zero());
    std::vector<Eigen::Matrix2d> grad(11, Eigen::Matrix2d::Zero());
    std::vector<double> q_val(11, 0.0);
    for (int c = 0; c < 2; ++c) {
      for (int a = 0; a < 3; ++a) {
        val[3 * c + a][c] = l[a];
        grad[3 * c + a].row(c) = T.grad.row(a);
      }
      val[9 + c][c] = bubble_value(l);
      grad[9 + c].row(c) = bubble_gradient(T, l).transpose();
    }
    for (int k = 0; k < 3; ++k) q_val[6 + k] = l[k];
    for (int i = 0; i < 11; ++i)
      for (int j = 0; j < 11; ++j) {
        const bool vi = i < 6 || i > 8, vj = j < 6 || j > 8;
        if (vi && vj) {
          const Eigen::Matrix2d ei = 0.5 * (grad[i] + grad[i].transpose());
          const Eigen::Matrix2d ej = 0.5 * (grad[j] + grad[j].transpose());
          K(i, j) += w * (2 * mu * (ei.array() * ej.array()).sum() + kappa * val[i].dot(val[j]));
        } else if (vi && !vj) {
          K(i, j) += -w * grad[i].trace() * q_val[j];
        } else if (!vi && vj) {
          K(i, j) += -w * grad[j].trace() * q_val[i];
        }
      }
  }
  return K;
}

TEST(MiniElement, CondensationEqualsSolvingWithTheBubbles) {
  for (double kappa : {0.0, 1.0e5}) {
    const double mu = 0.0035;
    ElementLoad load;
    load.F_V << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2;
    load.F_b << 0.01, -0.02;
    const CondensedElement ce = condensed_mini_element(kT, mu, kappa, load);
    EXPECT_LT((ce.K - ce.K.transpose()).norm(), 1e-12 * ce.K.norm()) << "not symmetric";

    const Eigen::MatrixXd full = uncondensed_by_quadrature(kT, mu, kappa);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(11);
    F.head(6) = load.F_V;
    F[9] = load.F_b[0];  // (tail(2) = ... trips a GCC 12 false -Wstringop-overflow)
    F[10] = load.F_b[1];
    // Fix v1, v2 at vertex 0 and v1 at vertex 1 (no rigid motion is left when
    // κ = 0), then compare the condensed solution with the full one elsewhere.
    auto kept = [](int i) { return i != 0 && i != 3 && i != 1; };
    std::vector<int> keep;
    for (int i = 0; i < 11; ++i)
      if (kept(i)) keep.push_back(i);
    const Eigen::MatrixXd Kf = full(keep, keep);
    const Eigen::VectorXd Ff = F(keep);
    const Eigen::VectorXd zf = Kf.fullPivLu().solve(Ff);
    std::vector<int> keep9;
    for (int i = 0; i < 9; ++i)
      if (kept(i)) keep9.push_back(i);
    const Eigen::MatrixXd Kc = ce.K(keep9, keep9);
    const Eigen::VectorXd Fc = ce.F(keep9);
    const Eigen::VectorXd zc = Kc.fullPivLu().solve(Fc);
    EXPECT_LT((zc - zf.head(6)).norm(), 1e-9 * zf.norm()) << "kappa " << kappa;
    // And the bubbles recovered from the vertex values match.
    const BubbleBlock bb = bubble_block(kT, mu, kappa);
    Vector9d local = Vector9d::Zero();
    for (std::size_t k = 0; k < keep9.size(); ++k) local[keep9[k]] = zc[static_cast<Eigen::Index>(k)];
    const Eigen::Vector2d beta = bb.A_bb_inv * (load.F_b - bb.E * local);
    EXPECT_LT((beta - zf.tail(2)).norm(), 1e-9 * zf.norm()) << "kappa " << kappa;
  }
}

}  // namespace
}  // namespace fsi::mini_element_test
