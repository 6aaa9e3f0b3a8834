#include "coupling/body_fitted_force.hpp"

#include "fem/vector_p1.hpp"

namespace fsi {

Eigen::Matrix2Xd pressure_nodal_forces(const std::vector<Point>& x, const Eigen::VectorXd& p) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::Matrix2Xd F = Eigen::Matrix2Xd::Zero(2, n);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const Point e = x[k + 1] - x[k];
    const Point n_ds(e.y(), -e.x());  // right-hand normal times the segment's length
    // ∫ p φ_k ds = |e| (2 p_k + p_{k+1}) / 6, ∫ p φ_{k+1} ds = |e| (p_k + 2 p_{k+1}) / 6
    F.col(k) -= n_ds * (2 * p[k] + p[k + 1]) / 6;
    F.col(k + 1) -= n_ds * (p[k] + 2 * p[k + 1]) / 6;
  }
  return F;
}

Eigen::VectorXd body_fitted_load(const Mesh& reference, const std::vector<int>& outline,
                                 const Eigen::Matrix2Xd& residual, const Eigen::VectorXd& pressure,
                                 const Eigen::VectorXd& u, PressureNormal normal) {
  const int nv = reference.num_vertices();
  Eigen::Matrix2Xd nodal = -residual;
  if (normal == PressureNormal::reference) {
    std::vector<Point> X, x;
    for (int v : outline) {
      X.push_back(reference.vertices[v]);
      x.push_back(X.back() + Point(u[v], u[nv + v]));
    }
    nodal += pressure_nodal_forces(X, pressure) - pressure_nodal_forces(x, pressure);
  }
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * nv);
  for (std::size_t k = 0; k < outline.size(); ++k)
    for (int c = 0; c < 2; ++c) b[dof(outline[k], c, nv)] += nodal(c, static_cast<Eigen::Index>(k));
  return b;
}

}  // namespace fsi
