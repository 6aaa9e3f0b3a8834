// Post-processing of a P1 displacement: stresses per triangle (plane strain).
#pragma once

#include <Eigen/Core>

#include "fem/p2.hpp"
#include "mesh/mesh.hpp"
#include "solid/elasticity.hpp"

namespace fsi {

// Von Mises stress on each triangle, plane strain: σ = λ tr(ε) I + 2μ ε, σ33 = λ tr(ε).
Eigen::VectorXd von_mises(const Mesh& mesh, const Lame& lame, const Eigen::VectorXd& u);
// The same for a P2 displacement (structure.element = "P2"), at each triangle's centroid.
Eigen::VectorXd von_mises(const P2Space& space, const Lame& lame, const Eigen::VectorXd& u);

}  // namespace fsi
