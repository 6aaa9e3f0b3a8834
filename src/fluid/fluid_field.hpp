// The discrete fluid fields as functions of position: v_h (P1 + bubble) and p_h
// (P1), evaluated by point location; a point outside D_h takes the value at the
// nearest point of D_h (SPEC §4 decision).
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <vector>

#include "fluid/penalised_stokes.hpp"
#include "fem/point_locator.hpp"

namespace fsi {

// A point whose fluid triangle lies outside the part of D where a solution is exact
// (FluidSolution::exact_on): a bug of the caller, who names the triangles it reads
// to PenalisedStokes::solve or ::solution.
struct FieldNotComputed : std::logic_error {
  using std::logic_error::logic_error;
};

struct FluidValue {
  Point v;
  double p = 0;
};

class FluidField {
 public:
  // `locator` must be built on the fluid mesh; both must outlive this object.
  FluidField(const PointLocator& locator, const FluidSolution& solution);

  FluidValue at(const Point& x) const;
  // Velocity and its gradient (row c = ∇v_c), bubble included, inside D_h.
  FluidValue at(const Location& where) const;
  Eigen::Matrix2d velocity_gradient(const Location& where) const;
  const PointLocator& locator() const { return locator_; }

 private:
  const PointLocator& locator_;
  const FluidSolution& solution_;
};

// ‖v_h‖_{L²(Ω)} over the region covered by `region` (a deformed structure mesh),
// exactly: its triangles are cut along the fluid mesh and each piece integrated by a
// rule exact for |v_h|² (degree 6).
double velocity_l2_over(const FluidField& field, const Mesh& region);
// The fluid triangles velocity_l2_over(field, region) may read (those meeting the
// bounding box of a region triangle), sorted, each once.
std::vector<int> triangles_meeting(const PointLocator& fluid, const Mesh& region);

}  // namespace fsi
