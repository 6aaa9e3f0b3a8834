#include "solid/newmark.hpp"

#include <Eigen/SparseCholesky>
#include <stdexcept>

#include "fem/quadrature.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

Newmark::Newmark(SparseMatrix M, double dt, std::vector<int> free_dofs)
    : M_(std::move(M)), dt_(dt), free_dofs_(std::move(free_dofs)) {
  if (!(dt_ > 0) || M_.rows() != M_.cols()) throw std::invalid_argument("Newmark: dt must be > 0 and M square");
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(M_.rows());
  mass_ = momentum(ones.head(M_.rows() / 2).replicate(2, 1)).x();
}

Point Newmark::momentum(const Eigen::VectorXd& v) const {
  const Eigen::VectorXd p = M_ * v;
  const Eigen::Index n = p.size() / 2;
  return {p.head(n).sum(), p.tail(n).sum()};
}

NewmarkState Newmark::start(double t0, Eigen::VectorXd u0, Eigen::VectorXd v0, const Eigen::VectorXd& r0,
                            ContactSolution contact) {
  t0_ = t0;
  const Eigen::Index n = M_.rows();
  std::vector<char> free(static_cast<std::size_t>(n), 0);
  for (int d : free_dofs_) free[d] = 1;
  for (Eigen::Index d = 0; d < n; ++d)
    if (!free[d]) u0[d] = v0[d] = 0;
  // The free dofs with mass: M's diagonal is positive there (consistent or lumped).
  std::vector<int> massive;
  for (int d : free_dofs_)
    if (M_.coeff(d, d) > 0) massive.push_back(d);
  std::vector<int> index(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < massive.size(); ++k) index[massive[k]] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < M_.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(M_, j); it; ++it)
      if (index[it.row()] >= 0 && index[it.col()] >= 0) t.emplace_back(index[it.row()], index[it.col()], it.value());
  SparseMatrix M_mm(static_cast<Eigen::Index>(massive.size()), static_cast<Eigen::Index>(massive.size()));
  M_mm.setFromTriplets(t.begin(), t.end());
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(M_mm);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("Newmark: the mass matrix is not positive definite");
  // Evaluated before the scatter: assigning the solve expression to a0(massive)
  // directly left a residual of 3e-2 relative (measured; Eigen 3.4's indexed view).
  const Eigen::VectorXd a_m = ldlt.solve(Eigen::VectorXd(r0(massive)));
  Eigen::VectorXd a0 = Eigen::VectorXd::Zero(n);
  a0(massive) = a_m;
  return {0, t0, std::move(u0), std::move(v0), std::move(a0), std::move(contact)};
}

Eigen::VectorXd Newmark::effective_load(const NewmarkState& s, const Eigen::VectorXd& b_next) const {
  const double c = operator_factor(dt_);
  return b_next + M_ * (c * (s.u + dt_ * s.v) + s.a);
}

NewmarkState Newmark::advance(const NewmarkState& s, ContactSolution next) const {
  NewmarkState out;
  out.step = s.step + 1;
  out.t = t0_ + out.step * dt_;
  out.u = next.u;
  out.a = operator_factor(dt_) * (out.u - s.u - dt_ * s.v) - s.a;
  out.v = s.v + 0.5 * dt_ * (s.a + out.a);
  out.contact = std::move(next);
  return out;
}

namespace {

// ∫ W(F(u)) on the P2 space, by its degree-4 rule (f_int's).
double p2_stored_energy(const P2Space& space, const Material& m, const Eigen::VectorXd& u) {
  double energy = 0;
  const int n = space.num_nodes();
  integrate_p2(space, triangle_rule(4), [&](int, const std::array<int, 6>& nodes, const P2Values& v, const Point&, double dx) {
    energy += m.energy(Matrix2::Identity() + p2_vector_at(nodes, v, u, n).grad) * dx;
  });
  return energy;
}

}  // namespace

double elastic_energy(const ElasticContactSolver& solver, const Eigen::VectorXd& u) {
  const Material& m = solver.material();
  if (m.model == MaterialModel::linear) return 0.5 * u.dot(solver.A_S() * u);
  if (const P2Space* p2 = solver.p2()) return p2_stored_energy(*p2, m, u);
  return stored_energy(solver.mesh(), m, u);
}

}  // namespace fsi
