// Point location in a triangulation through an R-tree (Boost.Geometry) of triangle
// bounding boxes, and the nearest point of the meshed domain for points outside it
// (SPEC §4: a deformed node outside D takes the value at the nearest point of D).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

struct Location {
  int triangle = -1;
  Eigen::Vector3d lambda;  // barycentric coordinates in that triangle
};

class PointLocator {
 public:
  explicit PointLocator(const Mesh& mesh);
  ~PointLocator();
  PointLocator(PointLocator&&) noexcept;
  PointLocator& operator=(PointLocator&&) noexcept;

  // The triangle containing p (barycentric coordinates ≥ −tol), if any.
  std::optional<Location> locate(const Point& p, double tol = 1e-12) const;
  // The closest point of the domain's boundary (a true boundary edge) to p.
  Point nearest_boundary_point(const Point& p) const;
  // locate(p), or if p is outside, the location of the nearest boundary point.
  Location locate_or_nearest(const Point& p) const;
  // Triangles whose bounding boxes meet the box [lo, hi].
  std::vector<int> triangles_in_box(const Point& lo, const Point& hi) const;

  const Mesh& mesh() const { return *mesh_; }

 private:
  struct Index;
  const Mesh* mesh_;
  std::unique_ptr<Index> index_;
};

}  // namespace fsi
