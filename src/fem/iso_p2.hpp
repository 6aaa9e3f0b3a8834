// The isoparametric P2 geometry of a mesh whose holes are circles: the P2 nodes of
// P2Space, the midpoint of every edge on a curved label moved onto its circle, and each
// triangle mapped from the reference triangle by the quadratic map
//     x(ξ) = Σ_i x_i N_i(ξ)   (N_i the six P2 basis functions, x_i the nodes),
// affine where no node moved. Per quadrature point it keeps what an assembly needs:
// the P2 basis values, their gradients in x (J⁻ᵀ ∇_ξ N), the P1 values λ(ξ) (the
// Taylor–Hood pressure, isoparametric too) and the weight |det J| dξ.
//
// Why curved: with straight edges a circle of radius r is met to O(h²/r) in position,
// which caps a P2 velocity's forces at second order; the quadratic map meets it to
// O(h³), below Taylor–Hood's error in the drag (Ciarlet & Raviart 1972; the DFG
// benchmarks' references all use curved cylinders).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "fem/p2.hpp"
#include "fem/quadrature.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// The edges labelled `label` lie on the circle |x − centre| = radius.
struct CircleBoundary {
  int label;
  Point centre;
  double radius;
};

// One quadrature point of one triangle.
struct IsoPoint {
  std::array<double, 6> N;          // P2 basis values
  Eigen::Matrix<double, 6, 2> grad;  // row i: ∇_x N_i
  Eigen::Vector3d lambda;            // P1 (reference barycentric) values
  Point x;                           // its position
  double dx;                         // weight × |det J| × reference area
};

class IsoP2Geometry {
 public:
  // Refers to `space` (and its mesh), which must outlive the geometry. `degree`: the
  // quadrature rule's exactness on affine triangles.
  IsoP2Geometry(const P2Space& space, const std::vector<CircleBoundary>& circles, int degree);

  const P2Space& space() const { return space_; }
  int num_nodes() const { return space_.num_nodes(); }
  // The nodes' positions (curved midpoints on their circles).
  const std::vector<Point>& nodes() const { return nodes_; }
  bool curved(int t) const { return curved_[t]; }
  int curved_triangles() const;
  // Triangle t's quadrature points (rule order).
  const IsoPoint* points(int t) const { return &points_[static_cast<std::size_t>(t) * per_triangle_]; }
  int points_per_triangle() const { return per_triangle_; }
  // Σ dx over all triangles: the domain's area with its curved holes.
  double area() const;

 private:
  IsoPoint point_of(int t, const Eigen::Vector3d& lambda, double weight) const;

  const P2Space& space_;
  std::vector<Point> nodes_;
  std::vector<char> curved_;
  int per_triangle_ = 0;
  std::vector<IsoPoint> points_;
};

// The reference P2 basis at barycentric λ: values and derivatives in ξ = (λ1, λ2).
void p2_reference(const Eigen::Vector3d& lambda, std::array<double, 6>& N, Eigen::Matrix<double, 6, 2>& dN);

}  // namespace fsi
