// Post-processing of a P1 displacement: stresses per triangle (plane strain).
#pragma once

#include <Eigen/Core>

#include "mesh/mesh.hpp"
#include "solid/elasticity.hpp"

namespace fsi {

// Von Mises stress on each triangle, plane strain: σ = λ tr(ε) I + 2μ ε, σ33 = λ tr(ε).
Eigen::VectorXd von_mises(const Mesh& mesh, const Lame& lame, const Eigen::VectorXd& u);

}  // namespace fsi
