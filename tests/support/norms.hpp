// Errors of P1 fields against exact functions, by quadrature (for convergence tests).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <vector>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "mesh/mesh.hpp"

namespace fsi::testing {

struct Errors {
  double l2 = 0, h1 = 0;  // ‖u − u_h‖_{L²}, |u − u_h|_{H¹}
};

// `values` holds `components` P1 fields one after the other (the paper's dof order).
// exact(x) returns the exact components, grad(x) their gradients (row c = ∇u_c).
inline Errors p1_errors(const Mesh& mesh, const Eigen::VectorXd& values, int components,
                        const std::function<Eigen::VectorXd(const Point&)>& exact,
                        const std::function<Eigen::MatrixXd(const Point&)>& grad) {
  const int nv = mesh.num_vertices();
  const TriangleRule rule = triangle_rule(8);
  Errors e;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P1Triangle T(mesh, t);
    const auto& tri = mesh.triangles[t];
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
      const Point x = T.point(rule.lambda[q]);
      const Eigen::VectorXd u = exact(x);
      const Eigen::MatrixXd g = grad(x);
      for (int c = 0; c < components; ++c) {
        double uh = 0;
        Eigen::RowVector2d gh = Eigen::RowVector2d::Zero();
        for (int a = 0; a < 3; ++a) {
          const double v = values[c * nv + tri[a]];
          uh += v * rule.lambda[q][a];
          gh += v * T.grad.row(a);
        }
        e.l2 += rule.w[q] * T.area * (u[c] - uh) * (u[c] - uh);
        e.h1 += rule.w[q] * T.area * (g.row(c) - gh).squaredNorm();
      }
    }
  }
  e.l2 = std::sqrt(e.l2);
  e.h1 = std::sqrt(e.h1);
  return e;
}

// Effective mesh size sqrt(area / triangles): comparable across unstructured meshes.
inline double mesh_size(const Mesh& mesh) {
  double area = 0;
  for (int t = 0; t < mesh.num_triangles(); ++t) area += mesh.area(t);
  return std::sqrt(area / mesh.num_triangles());
}

inline double rate(double e_coarse, double e_fine, double h_coarse, double h_fine) {
  return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
}

// Least-squares slope of y against x (a convergence rate from log–log data).
inline double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace fsi::testing
