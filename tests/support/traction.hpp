// The fluid's force on a boundary part by the traction integral ∮ σ(v_h, p_h) n ds,
// n out of the obstacle (into the fluid), from the triangle on each edge (P1 + bubble
// velocity, P1 pressure), 3 Gauss points per edge: an independent formula to set the
// residual method's forces (hole_force, fluid/stokes_residual.hpp) against. σ_h is one order less
// accurate than v_h, so the two agree only as h → 0.
#pragma once

#include <map>

#include "fem/quadrature.hpp"
#include "fluid/mini_element.hpp"
#include "fluid/penalised_stokes.hpp"
#include "mesh/mesh.hpp"

namespace fsi::testing {

inline Point traction_force(const Mesh& mesh, const FluidSolution& s, int label, double mu) {
  std::map<std::pair<int, int>, int> triangle_of;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) triangle_of[std::minmax(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])] = t;
  const LineRule line = gauss_legendre(3);
  Point F = Point::Zero();
  for (const BoundaryEdge& e : mesh.edges_on(label)) {
    const int t = triangle_of.at(std::minmax(e.v[0], e.v[1]));
    const auto& tri = mesh.triangles[t];
    const P1Triangle T(mesh, t);
    const Point a = mesh.vertices[e.v[0]], b = mesh.vertices[e.v[1]];
    Point n(b.y() - a.y(), a.x() - b.x());
    n.normalize();
    const Point inside = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0;
    if (n.dot(inside - a) < 0) n = -n;  // towards the fluid's triangle: out of the obstacle
    for (std::size_t q = 0; q < line.x.size(); ++q) {
      Eigen::Vector3d l = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        if (tri[k] == e.v[0]) l[k] = 1 - line.x[q];
        if (tri[k] == e.v[1]) l[k] = line.x[q];
      }
      Eigen::Matrix2d grad = s.bubble.col(t) * bubble_gradient(T, l).transpose();
      double p = 0;
      for (int k = 0; k < 3; ++k) {
        grad.row(0) += s.v1[tri[k]] * T.grad.row(k);
        grad.row(1) += s.v2[tri[k]] * T.grad.row(k);
        p += l[k] * s.p[tri[k]];
      }
      const Eigen::Matrix2d sigma = -p * Eigen::Matrix2d::Identity() + mu * (grad + grad.transpose());
      F += line.w[q] * (b - a).norm() * sigma * n;
    }
  }
  return F;
}

}  // namespace fsi::testing
