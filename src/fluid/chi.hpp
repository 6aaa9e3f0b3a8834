// The characteristic function χ of the deformed structure on the fluid mesh, P0
// (paper §7.2, SPEC §3): per fluid triangle, 1 if its barycentre lies in Ω_S^u
// (the default), or the fraction |T ∩ Ω_S^u| / |T| (option "area-fraction").
// Both go through spatial indices: the cost is that of the structure's triangles
// and the fluid triangles near them, not of the whole fluid mesh.
#pragma once

#include <Eigen/Core>
#include <string>

#include "mesh/clipping.hpp"  // triangle_intersection_area
#include "mesh/mesh.hpp"
#include "fem/point_locator.hpp"

namespace fsi {

class ChiComputer {
 public:
  ChiComputer(const Mesh& fluid_mesh, const PointLocator& fluid_locator, std::string rule);
  // χ on the fluid triangles for the structure occupying `deformed_structure`.
  Eigen::VectorXd operator()(const Mesh& deformed_structure) const;
  const std::string& rule() const { return rule_; }

 private:
  Eigen::VectorXd barycentre_rule(const Mesh& s) const;
  Eigen::VectorXd area_fraction_rule(const Mesh& s) const;

  const Mesh& fluid_;
  const PointLocator& locator_;
  std::string rule_;
};

}  // namespace fsi
