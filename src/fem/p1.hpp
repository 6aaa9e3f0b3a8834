// Geometry of one P1 triangle: area, barycentric coordinates and their gradients.
#pragma once

#include <Eigen/Core>
#include <array>

#include "mesh/mesh.hpp"

namespace fsi {

struct P1Triangle {
  double area = 0;
  std::array<Point, 3> x;                // vertex positions
  Eigen::Matrix<double, 3, 2> grad;      // row k: ∇λ_k (constant on T)

  P1Triangle(const Mesh& mesh, int t);
  P1Triangle(const Point& a, const Point& b, const Point& c);

  Point point(const Eigen::Vector3d& lambda) const {
    return lambda[0] * x[0] + lambda[1] * x[1] + lambda[2] * x[2];
  }
  // Barycentric coordinates of p (they sum to 1; all ≥ 0 iff p ∈ T).
  Eigen::Vector3d barycentric(const Point& p) const;
};

}  // namespace fsi
