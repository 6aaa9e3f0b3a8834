#include "fluid/fluid_field.hpp"

#include <cmath>

#include "fem/quadrature.hpp"

namespace fsi {

FluidField::FluidField(const PointLocator& locator, const FluidSolution& solution)
    : locator_(locator), solution_(solution) {}

FluidValue FluidField::at(const Point& x) const { return at(locator_.locate_or_nearest(x)); }

FluidValue FluidField::at(const Location& where) const {
  const auto& tri = locator_.mesh().triangles[where.triangle];
  const Eigen::Vector3d& l = where.lambda;
  FluidValue out;
  out.v = Point::Zero();
  for (int a = 0; a < 3; ++a) {
    out.v += l[a] * Point(solution_.v1[tri[a]], solution_.v2[tri[a]]);
    out.p += l[a] * solution_.p[tri[a]];
  }
  out.v += bubble_value(l) * solution_.bubble.col(where.triangle);
  return out;
}

Eigen::Matrix2d FluidField::velocity_gradient(const Location& where) const {
  const auto& tri = locator_.mesh().triangles[where.triangle];
  const P1Triangle T(locator_.mesh(), where.triangle);
  Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
  for (int a = 0; a < 3; ++a) {
    g.row(0) += solution_.v1[tri[a]] * T.grad.row(a);
    g.row(1) += solution_.v2[tri[a]] * T.grad.row(a);
  }
  const Eigen::Vector2d gb = bubble_gradient(T, where.lambda);
  g += solution_.bubble.col(where.triangle) * gb.transpose();
  return g;
}

double velocity_l2_over(const FluidField& field, const Mesh& mesh, int degree) {
  const TriangleRule rule = triangle_rule(degree);
  double sum = 0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P1Triangle T(mesh, t);
    for (std::size_t q = 0; q < rule.w.size(); ++q)
      sum += rule.w[q] * std::abs(T.area) * field.at(T.point(rule.lambda[q])).v.squaredNorm();
  }
  return std::sqrt(sum);
}

}  // namespace fsi
