// Quantities of a structure state read at given places: the P1 displacement at a
// point of the reference configuration, and the resultant of a nodal load.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fem/p2.hpp"
#include "fem/point_locator.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// u (2nv, paper ordering) interpolated at the reference point X (the nearest point of
// the mesh if X is outside it). With `p2` (structure.element = "P2"; `reference` its
// nodal mesh) u is the P2 field, interpolated by the quadratic basis of p2's element.
Point displacement_at(const Mesh& reference, const Eigen::VectorXd& u, const Point& X, const P2Space* p2 = nullptr);

// output.probes (SPEC §11): the same at fixed points, read many times (each
// fixed-point pass, history.csv), the points located once.
class ProbeSet {
 public:
  ProbeSet(const Mesh& reference, const std::vector<Point>& points, const P2Space* p2 = nullptr);
  // u at each point, in the points' order.
  std::vector<Point> displacements(const Eigen::VectorXd& u) const;
  bool empty() const { return at_.empty(); }

 private:
  const Mesh& reference_;
  const P2Space* p2_;
  std::vector<Location> at_;  // in p2's element mesh with P2
};

// [Σ F_x, Σ F_y] of a nodal load vector (2nv): tested with w = e_x, e_y, the force
// the load's integrals carry (eq. 33's fluid terms: the fluid's force on the structure).
Point resultant(const Eigen::VectorXd& load);

// The same over the vertices not on the label `clamped` (summary.json's
// structure_load): the load the elastic structure feels, the clamp taking the rest.
// The methods agree on it, not on `resultant`: eq. (33) tested with w = e_x, e_y
// includes the clamped vertices' rows, where −∫ p̃ div w sees a pressure on Γ_D as if
// fluid were there; the body-fitted load has none there (Γ_D is the wall Σ1). With the
// pressure level of about −500 Pa at the §7.2 beam the two differ by ≈ 500 Pa · H in x.
Point resultant_off(const Eigen::VectorXd& load, const Mesh& mesh, int clamped);

}  // namespace fsi
