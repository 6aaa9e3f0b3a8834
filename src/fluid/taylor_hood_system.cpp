#include "fluid/taylor_hood_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fsi {

TaylorHoodSystem::TaylorHoodSystem(const IsoP2Geometry& geometry, const TaylorHoodModel& model, const VectorField& f,
                                   const FluidBoundaryConditions& bc)
    : geometry_(geometry),
      model_(model),
      nn_(geometry.num_nodes()),
      nv_(geometry.space().mesh().num_vertices()) {
  set_data(f, bc);
  free_index_.assign(dofs(), -1);
  for (int d = 0; d < dofs(); ++d)
    if (std::isnan(prescribed_[d])) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }
  history_ = Eigen::VectorXd::Zero(2 * nn_);
  build_pattern();
}

void TaylorHoodSystem::set_data(const VectorField& f, const FluidBoundaryConditions& bc) {
  const Mesh& mesh = geometry_.space().mesh();
  const int per = geometry_.points_per_triangle();
  f_at_.resize(static_cast<std::size_t>(per) * mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int q = 0; q < per; ++q) f_at_[static_cast<std::size_t>(t) * per + q] = f(geometry_.points(t)[q].x);

  // NaN marks a free dof; the later label in dirichlet_labels decides at a shared node.
  Eigen::VectorXd z = Eigen::VectorXd::Constant(dofs(), std::numeric_limits<double>::quiet_NaN());
  for (int label : bc.dirichlet_labels) {
    const VectorField* value = &bc.g;
    for (const auto& [l, g] : bc.dirichlet_values)
      if (l == label) value = &g;
    for (int node : geometry_.space().nodes_on(label)) {
      const Point g = (*value)(geometry_.nodes()[node]);
      for (int c = 0; c < 2; ++c) z[velocity_dof(c, node)] = g[c];
    }
  }
  if (!free_index_.empty())
    for (int d = 0; d < dofs(); ++d)
      if (std::isnan(z[d]) != (free_index_[d] >= 0))
        throw std::invalid_argument("TaylorHoodSystem::set_data: the velocity must be prescribed on the same labels");
  prescribed_ = std::move(z);
  bc_ = bc;
}

void TaylorHoodSystem::set_inertia(double mass, const Eigen::VectorXd& history) {
  if (mass != mass_) ++revision_;
  mass_ = mass;
  history_ = history.head(2 * nn_);
}

void TaylorHoodSystem::impose(Eigen::VectorXd& U) const {
  if (U.size() != dofs()) U = Eigen::VectorXd::Zero(dofs());
  for (int d = 0; d < dofs(); ++d)
    if (free_index_[d] < 0) U[d] = prescribed_[d];
}

std::array<int, 15> TaylorHoodSystem::local_dofs(int t) const {
  const std::array<int, 6>& node = geometry_.space().element(t);
  std::array<int, 15> d;
  for (int i = 0; i < 6; ++i) d[i] = velocity_dof(0, node[i]), d[6 + i] = velocity_dof(1, node[i]);
  for (int a = 0; a < 3; ++a) d[12 + a] = pressure_dof(node[a]);
  return d;
}

void TaylorHoodSystem::build_pattern() {
  const int nt = geometry_.space().mesh().num_triangles();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(nt) * 225);
  for (int t = 0; t < nt; ++t) {
    const std::array<int, 15> d = local_dofs(t);
    for (int i : d)
      for (int j : d)
        if (free_index_[i] >= 0 && free_index_[j] >= 0) entries.emplace_back(free_index_[i], free_index_[j], 1.0);
  }
  J_ = Eigen::SparseMatrix<double>(unknowns(), unknowns());
  J_.setFromTriplets(entries.begin(), entries.end());
  J_.makeCompressed();
  slot_.assign(static_cast<std::size_t>(nt) * 225, -1);
  const int* outer = J_.outerIndexPtr();
  const int* inner = J_.innerIndexPtr();
  for (int t = 0; t < nt; ++t) {
    const std::array<int, 15> d = local_dofs(t);
    for (int i = 0; i < 15; ++i)
      for (int j = 0; j < 15; ++j) {
        const int r = free_index_[d[i]], c = free_index_[d[j]];
        if (r < 0 || c < 0) continue;
        slot_[static_cast<std::size_t>(t) * 225 + 15 * i + j] =
            static_cast<int>(std::lower_bound(inner + outer[c], inner + outer[c + 1], r) - inner);
      }
  }
}

// Triangle t's residual r and (with `jacobian`) its Jacobian K at U, by the rule of the
// geometry (degree 5 by default: exact for the convection term on affine triangles).
void TaylorHoodSystem::element(int t, const Eigen::VectorXd& U, bool jacobian, Local& K, LocalVector& r) const {
  const std::array<int, 6>& node = geometry_.space().element(t);
  const double mu = model_.mu, rho = model_.rho;
  const bool symmetric = model_.form == ViscousForm::symmetric;
  const double m = mass_ + (kappa_.size() ? kappa_[t] : 0.0);
  Eigen::Matrix<double, 6, 2> V;  // nodal velocities
  Eigen::Matrix<double, 6, 2> H;  // nodal history
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 2; ++c) V(i, c) = U[velocity_dof(c, node[i])], H(i, c) = history_[velocity_dof(c, node[i])];
  const Eigen::Vector3d P(U[pressure_dof(node[0])], U[pressure_dof(node[1])], U[pressure_dof(node[2])]);
  K.setZero();
  r.setZero();
  const IsoPoint* points = geometry_.points(t);
  for (int q = 0; q < geometry_.points_per_triangle(); ++q) {
    const IsoPoint& x = points[q];
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> N(x.N.data());
    const Eigen::Vector2d w = V.transpose() * N, hist = H.transpose() * N;
    const Eigen::Matrix2d G = V.transpose() * x.grad;  // G(c, d) = ∂_d w_c
    const double p = P.dot(x.lambda), div = G.trace(), dx = x.dx;
    const Eigen::Matrix2d S = symmetric ? Eigen::Matrix2d(G + G.transpose()) : G;  // viscous flux / μ
    const Eigen::Vector2d conv = G * w;                                           // (w·∇)w
    const Eigen::Matrix<double, 6, 1> adv = x.grad * w;                           // w·∇N_j
    const Point& f = f_at_[static_cast<std::size_t>(t) * geometry_.points_per_triangle() + q];
    for (int c = 0; c < 2; ++c) {
      const double value = m * w[c] - hist[c] + rho * conv[c] - f[c];
      r.segment<6>(6 * c) += dx * (value * N + mu * x.grad * S.row(c).transpose() - p * x.grad.col(c));
    }
    r.segment<3>(12) -= dx * div * x.lambda;
    if (!jacobian) continue;
    const Eigen::Matrix<double, 6, 6> NN = N * N.transpose(), GG = x.grad * x.grad.transpose();
    for (int c = 0; c < 2; ++c) {
      K.block<6, 6>(6 * c, 6 * c) += dx * (m * NN + mu * GG + rho * N * adv.transpose());
      for (int e = 0; e < 2; ++e) {
        // (δ·∇)w: N_j ∂_e w_c; the symmetric form's ∂_c N_j ∂_e N_i.
        if (!picard_) K.block<6, 6>(6 * c, 6 * e) += dx * rho * G(c, e) * NN;
        if (symmetric) K.block<6, 6>(6 * c, 6 * e) += dx * mu * x.grad.col(e) * x.grad.col(c).transpose();
      }
      K.block<6, 3>(6 * c, 12) -= dx * x.grad.col(c) * x.lambda.transpose();
      K.block<3, 6>(12, 6 * c) -= dx * x.lambda * x.grad.col(c).transpose();
    }
  }
}

// −∫_Σ h·w on the traction labels (straight edges: the box's sides), P2 along an edge.
void TaylorHoodSystem::traction_residual(Eigen::VectorXd& R) const {
  const LineRule rule = gauss_legendre(4);
  const Mesh& mesh = geometry_.space().mesh();
  for (const auto& [label, h] : bc_.tractions)
    for (const BoundaryEdge& e : mesh.edges_on(label)) {
      const std::array<int, 3> node{e.v[0], e.v[1], geometry_.space().midpoint_of(e)};
      const Point a = mesh.vertices[e.v[0]], b = mesh.vertices[e.v[1]];
      for (std::size_t k = 0; k < rule.x.size(); ++k) {
        const double s = rule.x[k], ds = rule.w[k] * (b - a).norm();
        const std::array<double, 3> N{(1 - s) * (1 - 2 * s), s * (2 * s - 1), 4 * s * (1 - s)};
        const Point hq = h((1 - s) * a + s * b);
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 2; ++c) R[velocity_dof(c, node[i])] -= ds * hq[c] * N[i];
      }
    }
}

void TaylorHoodSystem::assemble(const Eigen::VectorXd& U, bool jacobian, Eigen::VectorXd& R) {
  R = Eigen::VectorXd::Zero(dofs());
  if (jacobian) std::fill(J_.valuePtr(), J_.valuePtr() + J_.nonZeros(), 0.0);
  Local K;
  LocalVector r;
  double* values = J_.valuePtr();
  for (int t = 0; t < geometry_.space().mesh().num_triangles(); ++t) {
    element(t, U, jacobian, K, r);
    const std::array<int, 15> d = local_dofs(t);
    for (int i = 0; i < 15; ++i) R[d[i]] += r[i];
    if (!jacobian) continue;
    const int* slots = &slot_[static_cast<std::size_t>(t) * 225];
    for (int i = 0; i < 15; ++i)
      for (int j = 0; j < 15; ++j)
        if (slots[15 * i + j] >= 0) values[slots[15 * i + j]] += K(i, j);
  }
  traction_residual(R);
}

Eigen::VectorXd TaylorHoodSystem::free_part(const Eigen::VectorXd& full) const {
  Eigen::VectorXd x(unknowns());
  for (int k = 0; k < unknowns(); ++k) x[k] = full[free_[k]];
  return x;
}

void TaylorHoodSystem::add_free(const Eigen::VectorXd& part, double scale, Eigen::VectorXd& full) const {
  for (int k = 0; k < unknowns(); ++k) full[free_[k]] += scale * part[k];
}

std::vector<char> TaylorHoodSystem::pressure_unknowns() const {
  std::vector<char> p(free_.size());
  for (std::size_t k = 0; k < free_.size(); ++k) p[k] = free_[k] >= 2 * nn_;
  return p;
}

}  // namespace fsi
