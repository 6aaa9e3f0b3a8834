#include "fluid/taylor_hood_flow.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/LU>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/timer.hpp"

namespace fsi {

TaylorHoodFlow::TaylorHoodFlow(TaylorHoodSystem& system, const TaylorHoodOptions& options)
    : system_(system), options_(options), solver_(make_sparse_solver(options.solver, options.linear)) {
  U_ = Eigen::VectorXd::Zero(system.dofs());
  U_nm1_ = U_;
}

double TaylorHoodFlow::residual_norm(const Eigen::VectorXd& U) {
  const Stopwatch clock;
  system_.assemble(U, false, R_);
  timing_.assembly += clock.elapsed();
  return system_.free_part(R_).norm();
}

void TaylorHoodFlow::factorize_at(const Eigen::VectorXd& U, bool picard) {
  Stopwatch clock;
  system_.set_picard(picard);
  system_.assemble(U, true, R_);
  system_.set_picard(false);
  timing_.assembly += clock.elapsed();
  clock = Stopwatch();
  if (!analysed_) {
    solver_->describe_system(system_.pressure_unknowns(), false);
    solver_->analyze(system_.jacobian());
    analysed_ = true;
  }
  solver_->factorize(system_.jacobian());
  factors_ = Factors{!picard, U, system_.mass(), system_.revision()};
  timing_.factorization += clock.elapsed();
}

Eigen::VectorXd TaylorHoodFlow::back_substitute() {
  const Stopwatch clock;
  Eigen::VectorXd delta = solve_counting_iterations(*solver_, -system_.free_part(R_), timing_.linear_iterations);
  timing_.solve += clock.elapsed();
  return delta;
}

Eigen::VectorXd TaylorHoodFlow::newton_direction(bool picard) {
  factorize_at(U_, picard);
  return back_substitute();
}

// Armijo's test on the full step and its halves down to a sixteenth; where none passes
// (far from the solution at a high Reynolds number) the step is taken back and a
// Picard step taken instead.
double TaylorHoodFlow::step_from(double r, double scale) {
  const Eigen::VectorXd delta = newton_direction(false);
  ++report_.total_steps;
  for (double length = 1; length >= 1.0 / 16; length /= 2) {
    Eigen::VectorXd trial = U_;
    system_.add_free(delta, length, trial);
    const double r_trial = residual_norm(trial) / scale;
    if (r_trial <= (1 - 1e-4 * length) * r) {
      U_ = std::move(trial);
      ++report_.steps;
      if (length < 1) ++report_.damped;
      return r_trial;
    }
  }
  ++report_.rejected;
  system_.add_free(newton_direction(true), 1.0, U_);
  ++report_.picard_steps, ++report_.total_picard_steps;
  return residual_norm(U_) / scale;
}

bool TaylorHoodFlow::factors_usable() const {
  return reuse_ && factors_.newton && factors_.revision == system_.revision();
}

// R_ holds R(U_) here (every step leaves it so).
bool TaylorHoodFlow::chord_step(double& r, double scale) {
  // Kept below a half, factors kept below a tenth: measured on DFG 2D-2 (docs/performance.md).
  constexpr double kAccept = 0.5, kKeep = 0.1;
  Eigen::VectorXd trial = U_;
  system_.add_free(back_substitute(), 1.0, trial);
  const double r_trial = residual_norm(trial) / scale;
  if (!(r_trial <= kAccept * r)) {
    factors_.newton = false;
    return false;
  }
  if (r_trial > kKeep * r) factors_.newton = false;
  U_ = std::move(trial);
  r = r_trial;
  ++report_.steps, ++report_.total_steps, ++chord_steps_;
  return true;
}

bool TaylorHoodFlow::factors_state(Eigen::VectorXd& U, double& mass) const {
  if (!factors_usable()) return false;
  U = factors_.U, mass = factors_.mass;
  return true;
}

void TaylorHoodFlow::restore_factors(const Eigen::VectorXd& U, double mass) {
  const Eigen::VectorXd history = Eigen::VectorXd::Zero(2 * system_.velocity_nodes());
  system_.set_inertia(mass, history);  // the Jacobian does not depend on the history
  factorize_at(U, false);               // (R_ is assembled again by the next solve)
}

const Eigen::VectorXd& TaylorHoodFlow::solve() {
  system_.impose(U_);
  Eigen::VectorXd lifted = Eigen::VectorXd::Zero(system_.dofs());
  system_.impose(lifted);
  const double load = residual_norm(lifted);
  const double scale = load > 0 ? load : 1.0;
  double r = residual_norm(U_) / scale;
  report_.residuals = {r};
  report_.steps = report_.damped = report_.picard_steps = report_.rejected = 0;
  ++report_.solves;
  for (int k = 0; r > options_.tol; ++k) {
    if (k == options_.max_steps || !std::isfinite(r)) fail();
    if (!(factors_usable() && chord_step(r, scale))) r = step_from(r, scale);
    report_.residuals.push_back(r);
  }
  report_.max_final_residual = std::max(report_.max_final_residual, r);
  return U_;
}

void TaylorHoodFlow::fail() const {
  std::string history;
  for (double r : report_.residuals) history += (history.empty() ? "" : ", ") + approx(r, 2);
  throw SolverFailure("Newton's method (Taylor–Hood) did not reach fluid.newton_tol = " + shortest(options_.tol) +
                      " in " + std::to_string(options_.max_steps) + " steps (" + std::to_string(report_.picard_steps) +
                      " of them Picard's, " + std::to_string(report_.damped) + " damped); relative residuals " + history +
                      ": a steady flow may not exist at this Reynolds number (lower fluid.rho or the inflow, or "
                      "raise fluid.newton_max_steps)");
}

void TaylorHoodFlow::start(double rho, TimeScheme scheme, double dt, const Eigen::VectorXd& initial, double t0) {
  rho_ = rho, scheme_ = scheme, dt_ = dt, t0_ = t0, steps_ = 0;
  reuse_ = options_.reuse_factors;
  U_ = initial;
  U_nm1_ = initial;
}

void TaylorHoodFlow::restore(int steps, const Eigen::VectorXd& u_n, const Eigen::VectorXd& u_nm1) {
  steps_ = steps;
  U_ = u_n;
  U_nm1_ = u_nm1;
}

const Eigen::VectorXd& TaylorHoodFlow::step(const std::function<void(double)>& data) {
  const BdfWeights w = bdf_weights(scheme_, steps_);
  const int nv2 = 2 * system_.velocity_nodes();
  if (data) data(t0_ + (steps_ + 1) * dt_);
  system_.set_inertia(rho_ * w.alpha / dt_,
                      rho_ * (w.beta1 * U_.head(nv2) + w.beta2 * U_nm1_.head(nv2)) / dt_);
  const Eigen::VectorXd u_n = U_;
  // Newton starts from the linear extrapolation 2vⁿ − vⁿ⁻¹ (one step fewer, measured on
  // DFG 2D-2), from vⁿ on the first step.
  if (steps_ > 0) U_ = 2 * u_n - U_nm1_;
  try {
    solve();
  } catch (...) {
    U_ = u_n;  // the state stays at t
    throw;
  }
  U_nm1_ = u_n;
  ++steps_;
  return U_;
}

std::vector<Point> TaylorHoodFlow::forces(const std::vector<int>& labels) {
  system_.assemble(U_, false, R_);
  std::vector<Point> F(labels.size(), Point::Zero());
  for (std::size_t k = 0; k < labels.size(); ++k)
    for (int node : system_.geometry().space().nodes_on(labels[k]))
      for (int c = 0; c < 2; ++c) F[k][c] -= R_[system_.velocity_dof(c, node)];
  return F;
}

FluidSolution TaylorHoodFlow::vertex_view() const {
  const Mesh& mesh = system_.geometry().space().mesh();
  const int nv = mesh.num_vertices(), nn = system_.velocity_nodes();
  FluidSolution s;
  s.v1 = U_.segment(0, nv);
  s.v2 = U_.segment(nn, nv);
  s.p = U_.segment(2 * nn, nv);
  s.bubble = Eigen::Matrix2Xd::Zero(2, mesh.num_triangles());
  return s;
}

FluidValue TaylorHoodFlow::at(int t, const Eigen::Vector3d& straight_lambda) const {
  const IsoP2Geometry& g = system_.geometry();
  const std::array<int, 6>& node = g.space().element(t);
  Eigen::Vector3d l = straight_lambda;
  std::array<double, 6> N;
  Eigen::Matrix<double, 6, 2> dN;
  if (g.curved(t)) {  // x(ξ) = target by Newton from the straight triangle's ξ (a few steps: the map is near affine)
    const Point target = l[0] * g.nodes()[node[0]] + l[1] * g.nodes()[node[1]] + l[2] * g.nodes()[node[2]];
    for (int k = 0; k < 8; ++k) {
      p2_reference(l, N, dN);
      Point x = Point::Zero();
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (int i = 0; i < 6; ++i) x += N[i] * g.nodes()[node[i]], J += g.nodes()[node[i]] * dN.row(i);
      const Eigen::Vector2d step = J.inverse() * (target - x);
      l[1] += step[0], l[2] += step[1], l[0] = 1 - l[1] - l[2];
      if (step.norm() < 1e-14) break;
    }
  }
  p2_reference(l, N, dN);
  FluidValue v;
  v.v.setZero();
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 2; ++c) v.v[c] += N[i] * U_[system_.velocity_dof(c, node[i])];
  for (int a = 0; a < 3; ++a) v.p += l[a] * U_[system_.pressure_dof(node[a])];
  return v;
}

TaylorHoodErrors taylor_hood_errors(const TaylorHoodSystem& system, const Eigen::VectorXd& U,
                                    const std::function<Point(const Point&)>& v,
                                    const std::function<Eigen::Matrix2d(const Point&)>& grad_v,
                                    const std::function<double(const Point&)>& p, bool pressure_mean) {
  const IsoP2Geometry& g = system.geometry();
  const int nt = g.space().mesh().num_triangles();
  // The means of p and p_h (subtracted where asked).
  double area = 0, mean = 0, mean_h = 0;
  const auto values = [&](int t, const IsoPoint& x, Point& vh, Eigen::Matrix2d& Gh, double& ph) {
    const std::array<int, 6>& node = g.space().element(t);
    vh.setZero(), Gh.setZero(), ph = 0;
    for (int i = 0; i < 6; ++i)
      for (int c = 0; c < 2; ++c) {
        const double u = U[system.velocity_dof(c, node[i])];
        vh[c] += u * x.N[i];
        Gh.row(c) += u * x.grad.row(i);
      }
    for (int a = 0; a < 3; ++a) ph += U[system.pressure_dof(node[a])] * x.lambda[a];
  };
  Point vh;
  Eigen::Matrix2d Gh;
  double ph;
  if (pressure_mean)
    for (int t = 0; t < nt; ++t)
      for (int q = 0; q < g.points_per_triangle(); ++q) {
        const IsoPoint& x = g.points(t)[q];
        values(t, x, vh, Gh, ph);
        area += x.dx, mean += p(x.x) * x.dx, mean_h += ph * x.dx;
      }
  if (area > 0) mean /= area, mean_h /= area;
  TaylorHoodErrors e;
  for (int t = 0; t < nt; ++t)
    for (int q = 0; q < g.points_per_triangle(); ++q) {
      const IsoPoint& x = g.points(t)[q];
      values(t, x, vh, Gh, ph);
      e.velocity_l2 += (vh - v(x.x)).squaredNorm() * x.dx;
      e.velocity_h1 += (Gh - grad_v(x.x)).squaredNorm() * x.dx;
      e.pressure_l2 += std::pow((ph - mean_h) - (p(x.x) - mean), 2) * x.dx;
    }
  e.velocity_l2 = std::sqrt(e.velocity_l2), e.velocity_h1 = std::sqrt(e.velocity_h1);
  e.pressure_l2 = std::sqrt(e.pressure_l2);
  return e;
}

}  // namespace fsi
