#include "coupling/force_transfer.hpp"

#include "solid/hyperelastic.hpp"

#include <stdexcept>
#include <string>

#include "fem/integration.hpp"
#include "solid/elasticity.hpp"  // A_S with Lamé (0, μ_F), B

namespace fsi {
namespace {

// The fields and u must live on the force's space: 2n, n, 2n entries.
void check_sizes(const SampledFluid& s, const Eigen::VectorXd& u, int n) {
  if (s.v.size() == 2 * n && s.p.size() == n && u.size() == 2 * n) return;
  throw std::invalid_argument("FluidForce: the sampled v has " + std::to_string(s.v.size()) + " entries, p " +
                              std::to_string(s.p.size()) + ", u " + std::to_string(u.size()) + "; the space has " +
                              std::to_string(n) + " nodes (2n, n, 2n expected)");
}

// A per-component operator (the P1 interpolation, or its transpose) applied to both
// components of a vector field in paper ordering (x values, then y values).
template <typename Operator>
Eigen::VectorXd per_component(const Operator& A, const Eigen::VectorXd& field) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd out(2 * A.rows());
  out << A * field.head(n), A * field.tail(n);
  return out;
}

}  // namespace

SampledFluid sample_at_deformed_vertices(const FluidField& field, const Mesh& reference,
                                         const Eigen::VectorXd& u) {
  return sample_at(field, locate_deformed_vertices(field.locator(), reference, u));
}

std::vector<Location> locate_deformed_vertices(const PointLocator& fluid, const Mesh& reference,
                                               const Eigen::VectorXd& u) {
  const int nv = reference.num_vertices();
  std::vector<Location> where;
  where.reserve(nv);
  for (int i = 0; i < nv; ++i) where.push_back(fluid.locate_or_nearest(reference.vertices[i] + Point(u[i], u[nv + i])));
  return where;
}

std::vector<int> triangles_of(const std::vector<Location>& where) {
  std::vector<int> triangles;
  triangles.reserve(where.size());
  for (const Location& w : where) triangles.push_back(w.triangle);
  return triangles;
}

SampledFluid sample_at(const FluidField& field, const std::vector<Location>& where) {
  const int nv = static_cast<int>(where.size());
  SampledFluid s{Eigen::VectorXd(2 * nv), Eigen::VectorXd(nv)};
  for (int i = 0; i < nv; ++i) {
    const FluidValue value = field.at(where[i]);
    s.v[i] = value.v.x();
    s.v[nv + i] = value.v.y();
    s.p[i] = value.p;
  }
  return s;
}

FluidForce::FluidForce(const Mesh& reference, double mu_F, double eps, const VectorField& f_F, ForceModel model,
                       int sampling)
    : refinement_(sampling > 1 ? std::make_shared<const UniformRefinement>(refine_uniformly(reference, sampling)) : nullptr),
      mesh_(refinement_ ? refinement_->fine : reference),
      mu_F_(mu_F),
      eps_(eps),
      model_(model),
      f_F_(f_F),
      K_mu_(assemble_elasticity(mesh_, Lame{0.0, mu_F})),  // λ = 0, μ = μ_F: 2μ_F ε:ε
      B_(assemble_divergence(mesh_)),
      M_(assemble_vector_mass(mesh_)) {}

Eigen::VectorXd FluidForce::body_force(const Eigen::VectorXd& u, bool jacobian) const {
  const int nv = mesh_.num_vertices();
  Eigen::VectorXd body = Eigen::VectorXd::Zero(2 * nv);
  integrate_on_triangles(mesh_, triangle_rule(2), [&](int tri, const P1Triangle& T, const TrianglePoint& q) {
    const auto& v = mesh_.triangles[tri];
    Point x = q.x;  // the point's deformed position
    for (int a = 0; a < 3; ++a) x += q.lambda[a] * Point(u[v[a]], u[nv + v[a]]);
    const Point f = f_F_(x) * q.dx * (jacobian ? deformation_gradient(T, v, u, nv).determinant() : 1.0);
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) body[dof(v[a], c, nv)] -= f[c] * q.lambda[a];
  });
  return body;
}

Eigen::VectorXd FluidForce::to_samples(const Eigen::VectorXd& u) const {
  if (!refinement_) return u;
  const Eigen::Index n = refinement_->P.cols();
  if (u.size() != 2 * n) throw std::invalid_argument("FluidForce::to_samples: u has " + std::to_string(u.size()) +
                                                     " entries; the structure has " + std::to_string(n) + " vertices");
  return per_component(refinement_->P, u);
}

// Viscous, pressure, penalty and body-force terms of eq. (33), on the integrals' mesh,
// then (sampling > 1) restricted to the structure's vertices: w = Σ P_ij φ_i^fine.
Eigen::VectorXd FluidForce::operator()(const SampledFluid& s, const Eigen::VectorXd& u) const {
  const Eigen::VectorXd uf = to_samples(u);
  check_sizes(s, uf, space_ ? space_->num_nodes() : mesh_.num_vertices());
  Eigen::VectorXd load;
  if (model_ == ForceModel::large) load = space_ ? p2_large(s, uf) : large(s, uf);  // P2: p2_force.cpp
  else load = K_mu_ * s.v - B_ * s.p + (M_ * s.v) / eps_ + (space_ ? p2_body_force(uf) : body_force(uf));
  return refinement_ ? per_component(refinement_->P.transpose(), load) : load;
}

}  // namespace fsi
