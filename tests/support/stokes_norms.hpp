// Errors of a mini-element solution (bubble included) against exact fields.
#pragma once

#include <functional>

#include "fem/quadrature.hpp"
#include "fluid/penalised_stokes.hpp"

namespace fsi::testing {

struct StokesErrors {
  double v_l2 = 0, v_h1 = 0, p_l2 = 0;
};

inline StokesErrors mini_errors(const Mesh& mesh, const FluidSolution& s,
                                const std::function<Point(const Point&)>& v,
                                const std::function<Eigen::Matrix2d(const Point&)>& grad_v,
                                const std::function<double(const Point&)>& p,
                                const std::function<bool(const Point&)>& include = nullptr) {
  const TriangleRule rule = triangle_rule(8);
  StokesErrors e;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P1Triangle T(mesh, t);
    const auto& tri = mesh.triangles[t];
    if (include && !include(T.point(Eigen::Vector3d::Constant(1.0 / 3)))) continue;
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const Eigen::Vector3d& l = rule.lambda[q];
      const Point x = T.point(l);
      Point vh = bubble_value(l) * s.bubble.col(t);
      Eigen::Matrix2d gh = s.bubble.col(t) * bubble_gradient(T, l).transpose();
      double ph = 0;
      for (int a = 0; a < 3; ++a) {
        vh += l[a] * Point(s.v1[tri[a]], s.v2[tri[a]]);
        gh.row(0) += s.v1[tri[a]] * T.grad.row(a);
        gh.row(1) += s.v2[tri[a]] * T.grad.row(a);
        ph += l[a] * s.p[tri[a]];
      }
      const double w = rule.w[q] * T.area;
      e.v_l2 += w * (v(x) - vh).squaredNorm();
      e.v_h1 += w * (grad_v(x) - gh).squaredNorm();
      e.p_l2 += w * (p(x) - ph) * (p(x) - ph);
    }
  }
  e.v_l2 = std::sqrt(e.v_l2);
  e.v_h1 = std::sqrt(e.v_h1);
  e.p_l2 = std::sqrt(e.p_l2);
  return e;
}

}  // namespace fsi::testing
