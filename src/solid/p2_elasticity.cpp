#include "solid/p2_elasticity.hpp"

#include <algorithm>
#include <vector>

#include "fem/quadrature.hpp"

namespace fsi {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

Matrix2 gradient_at(const std::array<int, 6>& nodes, const P2Values& v, const Eigen::VectorXd& u, int n) {
  Matrix2 F = Matrix2::Identity();
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 2; ++c) F.row(c) += u[dof(nodes[i], c, n)] * v.grad.row(i);
  return F;
}

SparseMatrix from_triplets(const Triplets& entries, int n) {
  SparseMatrix K(2 * n, 2 * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace

SparseMatrix assemble_elasticity(const P2Space& space, const Lame& lame) {
  const int n = space.num_nodes();
  Triplets entries;
  entries.reserve(144 * 3 * space.mesh().triangles.size());
  integrate_p2(space, triangle_rule(2), [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            entries.emplace_back(dof(nodes[a], c, n), dof(nodes[b], d, n),
                                 dx * elasticity_entry(lame, v.grad.row(a), v.grad.row(b), c, d));
  });
  return from_triplets(entries, n);
}

Eigen::VectorXd internal_force(const P2Space& space, const Material& m, const Eigen::VectorXd& u) {
  const int n = space.num_nodes();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
  integrate_p2(space, triangle_rule(4), [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
    const Matrix2 P = m.stress(gradient_at(nodes, v, u, n));
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 2; ++c) f[dof(nodes[a], c, n)] += dx * P.row(c).dot(v.grad.row(a));
  });
  return f;
}

SparseMatrix tangent_stiffness(const P2Space& space, const Material& m, const Eigen::VectorXd& u) {
  const int n = space.num_nodes();
  Triplets entries;
  entries.reserve(144 * 6 * space.mesh().triangles.size());
  integrate_p2(space, triangle_rule(4), [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
    const Eigen::Matrix4d A = m.moduli(gradient_at(nodes, v, u, n));
    for (int b = 0; b < 6; ++b)
      for (int d = 0; d < 2; ++d) {
        const Eigen::Vector4d Ag = A.middleCols<2>(2 * d) * v.grad.row(b).transpose();
        for (int a = 0; a < 6; ++a)
          for (int c = 0; c < 2; ++c)
            entries.emplace_back(dof(nodes[a], c, n), dof(nodes[b], d, n),
                                 dx * (Ag[2 * c] * v.grad(a, 0) + Ag[2 * c + 1] * v.grad(a, 1)));
      }
  });
  return from_triplets(entries, n);
}

Eigen::VectorXd assemble_volume_load(const P2Space& space, const VectorField& f, int degree) {
  const int n = space.num_nodes();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * n);
  integrate_p2(space, triangle_rule(degree), [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point& x, double dx) {
    const Point fx = f(x) * dx;
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 2; ++c) b[dof(nodes[a], c, n)] += fx[c] * v.N[a];
  });
  return b;
}

// On an edge p → q with midpoint node m, s ∈ [0, 1]: N_p = (1 − s)(1 − 2s), N_m = 4s(1 − s),
// N_q = s(2s − 1), the traces of the triangle's basis.
Eigen::VectorXd assemble_surface_load(const P2Space& space, int label, const VectorField& h, int points) {
  const Mesh& mesh = space.mesh();
  const int n = space.num_nodes();
  const LineRule rule = gauss_legendre(points);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * n);
  for (const BoundaryEdge& e : mesh.edges_on(label)) {
    const Point &p = mesh.vertices[e.v[0]], &q = mesh.vertices[e.v[1]];
    const int nodes[3] = {e.v[0], space.midpoint_of(e), e.v[1]};
    const double length = (q - p).norm();
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      const double s = rule.x[k];
      const double N[3] = {(1 - s) * (1 - 2 * s), 4 * s * (1 - s), s * (2 * s - 1)};
      const Point hx = h((1 - s) * p + s * q) * (rule.w[k] * length);
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 2; ++c) b[dof(nodes[a], c, n)] += hx[c] * N[a];
    }
  }
  return b;
}

std::vector<int> clamped_dofs(const P2Space& space, int label) {
  return both_components(space.nodes_on(label), space.num_nodes());
}

}  // namespace fsi
