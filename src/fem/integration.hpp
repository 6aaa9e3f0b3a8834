// The element loops every assembly shares: over the triangles of a mesh, and over the
// points of a quadrature rule on its triangles or on a set of boundary edges. A kernel
// sees one element or one point at a time (its position, its measure, the P1 shape
// values there); what it adds where is its own. Written once so that P2 and other
// elements (issue 14) change one place; the arithmetic is the loops' it replaced, term
// for term, so that every result stays bit for bit (Table 1).
#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// kernel(t, T) for every triangle t of `mesh`, T its P1 geometry.
template <class Kernel>
void for_each_triangle(const Mesh& mesh, Kernel&& kernel) {
  for (int t = 0; t < mesh.num_triangles(); ++t) kernel(t, P1Triangle(mesh, t));
}

// The sparse matrix (rows × cols) of what kernel(t, T, add) adds on each triangle,
// add(row, col, value), reserving `per_triangle` entries each: the triplet scaffolding
// of every P1 matrix, written once. Duplicates are summed in the order they were added,
// as the loops it replaced did, so the matrices stay bit for bit.
template <class Kernel>
Eigen::SparseMatrix<double> assemble_on_triangles(const Mesh& mesh, int rows, int cols, int per_triangle,
                                                  Kernel&& kernel) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(per_triangle) * mesh.triangles.size());
  const auto add = [&entries](int row, int col, double value) { entries.emplace_back(row, col, value); };
  for_each_triangle(mesh, [&](int t, const P1Triangle& T) { kernel(t, T, add); });
  Eigen::SparseMatrix<double> A(rows, cols);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

// A point of a triangle rule: barycentric coordinates (the P1 shape values), the
// position, and the weight times the area (dx).
struct TrianglePoint {
  const Eigen::Vector3d& lambda;
  Point x;
  double dx;
};

// kernel(t, T, point) for every point of `rule` on every triangle t.
template <class Kernel>
void integrate_on_triangles(const Mesh& mesh, const TriangleRule& rule, Kernel&& kernel) {
  for_each_triangle(mesh, [&](int t, const P1Triangle& T) {
    for (std::size_t q = 0; q < rule.w.size(); ++q)
      kernel(t, T, TrianglePoint{rule.lambda[q], T.point(rule.lambda[q]), rule.w[q] * T.area});
  });
}

// A point of a line rule on a boundary edge v[0] → v[1]: the P1 shape values of its two
// vertices (1 − s, s), the position and the weight times the edge's length (ds).
struct EdgePoint {
  std::array<double, 2> phi;
  Point x;
  double ds;
};

// kernel(edge, point) for every point of `rule` on every edge of `edges`.
template <class Kernel>
void integrate_on_edges(const Mesh& mesh, const std::vector<BoundaryEdge>& edges, const LineRule& rule,
                        Kernel&& kernel) {
  for (const BoundaryEdge& e : edges) {
    const Point& p = mesh.vertices[e.v[0]];
    const Point& q = mesh.vertices[e.v[1]];
    const double length = (q - p).norm();
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      const double s = rule.x[k];
      kernel(e, EdgePoint{{1 - s, s}, (1 - s) * p + s * q, rule.w[k] * length});
    }
  }
}

}  // namespace fsi
