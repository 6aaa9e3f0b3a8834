#include "solid/stress.hpp"

#include <cmath>

#include "fem/p1.hpp"
#include "solid/p2_elasticity.hpp"

namespace fsi {

namespace {

// Plane strain: σ = λ tr(ε) I + 2μ ε, σ33 = λ tr(ε), ε = sym(∇u).
double von_mises_of(const Lame& lame, const Eigen::Matrix2d& grad_u) {
  const Eigen::Matrix2d eps = 0.5 * (grad_u + grad_u.transpose());
  const double tr = eps.trace();
  const Eigen::Matrix2d s = lame.lambda * tr * Eigen::Matrix2d::Identity() + 2 * lame.mu * eps;
  const double s33 = lame.lambda * tr;
  return std::sqrt(0.5 * ((s(0, 0) - s(1, 1)) * (s(0, 0) - s(1, 1)) + (s(1, 1) - s33) * (s(1, 1) - s33) +
                          (s33 - s(0, 0)) * (s33 - s(0, 0))) +
                   3 * s(0, 1) * s(0, 1));
}

}  // namespace

Eigen::VectorXd von_mises(const Mesh& mesh, const Lame& lame, const Eigen::VectorXd& u) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd out(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P1Triangle T(mesh, t);
    Eigen::Matrix2d grad_u = Eigen::Matrix2d::Zero();  // (∇u)_{cd} = ∂_d u_c
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) grad_u.row(c) += u[dof(mesh.triangles[t][a], c, nv)] * T.grad.row(a);
    out[t] = von_mises_of(lame, grad_u);
  }
  return out;
}

Eigen::VectorXd von_mises(const P2Space& space, const Lame& lame, const Eigen::VectorXd& u) {
  const Mesh& mesh = space.mesh();
  Eigen::VectorXd out(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P2Values v = p2_values(P1Triangle(mesh, t), Eigen::Vector3d::Constant(1.0 / 3));
    out[t] = von_mises_of(lame, p2_vector_at(space.element(t), v, u, space.num_nodes()).grad);
  }
  return out;
}

}  // namespace fsi
