// Quadrature rules: Gauss–Legendre on [0,1] and collapsed (Duffy) Gauss rules on
// the triangle, exact for polynomials of any requested degree.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace fsi {

struct LineRule {
  std::vector<double> x;  // points in [0,1]
  std::vector<double> w;  // weights, summing to 1
};
// n-point Gauss–Legendre on [0,1]: exact to degree 2n−1.
LineRule gauss_legendre(int n);

struct TriangleRule {
  std::vector<Eigen::Vector3d> lambda;  // barycentric coordinates of the points
  std::vector<double> w;                // weights, summing to 1 (multiply by |T|)
};
// Rule exact for polynomials of total degree ≤ `degree` on any triangle.
TriangleRule triangle_rule(int degree);

}  // namespace fsi
