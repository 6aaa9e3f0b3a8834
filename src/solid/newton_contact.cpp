// Newton's method for a hyperelastic structure with frictionless contact (SPEC §11):
// at u_k, the QP in the increment δ = u_{k+1} − u_k (free dofs)
//     min ½ δᵀ K_T(u_k) δ + r(u_k)ᵀ δ   s.t.   C δ ≥ c_lb − C x_k,
// r(u) = f_int(u) − b, is the linearised equilibrium K_T δ + r = Cᵀα with the
// contact's complementarity kept exactly in every step (the active set found by the
// QP, warm-started from the step before). The iteration stops when the nonlinear
// equilibrium's relative residual ‖f_int(u) − b − Cᵀα‖∞ / scale ≤ newton_tol, or, in
// an inexact solve, when a step moves no node by more than newton_step_tol.
// A step that folds a triangle or does not reduce that residual is halved (a
// feasible point: x_k and x_{k+1} both satisfy the linear constraint); if Newton
// still fails, the load is applied in 2, 4, ... 64 increments.
#include <cmath>
#include <cstdio>
#include <string>

#include "common/errors.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {
namespace {

constexpr int kMaxCuts = 8;
constexpr int kMaxLoadSteps = 64;

// "1e+00 3.2e-01 ... 8.7e-09": at most the first 4 and last 4 of a residual history.
std::string history_text(const std::vector<double>& h) {
  std::string out;
  char number[16];
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (h.size() > 8 && k == 4) out += "... ", k = h.size() - 4;
    std::snprintf(number, sizeof number, "%.2g ", h[k]);
    out += number;
  }
  return out.empty() ? "none" : out.substr(0, out.size() - 1);
}

}  // namespace

void ElasticContactSolver::set_material(const Material& material) {
  material_ = material;
  solver_.refactorise_often = material_.model != MaterialModel::linear;
  solver_.set_operator(A_free_, C_free_);
  if (material_.model != MaterialModel::linear) {
    assembler_ = p2_ ? std::make_unique<FreeDofAssembler>(p2_->space, free_dofs_, A_free_)
                     : std::make_unique<FreeDofAssembler>(mesh_, free_dofs_, A_free_);
    K_ = A_free_;
  }
}

// The backward error of the equilibrium: ‖f − b − Cᵀα‖∞ / (‖K‖∞‖x‖∞ + ‖b‖∞ + ‖Cᵀα‖∞),
// x the free dofs, K the tangent (the QP's KKT measure, qp_problem.hpp). Relative to
// ‖b‖ alone the floor is the structure's condition, not round-off: on Turek–Hron's
// flag (88 × 5 cells) even the linear Cholesky solve leaves ‖Au − b‖∞/‖b‖∞ = 6e-9,
// and Newton stalled at 1e-7.
double ElasticContactSolver::equilibrium_residual(const Eigen::VectorXd& f, const Eigen::VectorXd& b,
                                                  const Eigen::VectorXd& alpha, const Eigen::VectorXd& x,
                                                  double K_norm) const {
  const Eigen::VectorXd contact = alpha.size() ? Eigen::VectorXd(C_free_.transpose() * alpha)
                                               : Eigen::VectorXd::Zero(f.size());
  const double scale = std::max(K_norm * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>() +
                                    contact.lpNorm<Eigen::Infinity>(),
                                1e-300);
  return (f - b - contact).lpNorm<Eigen::Infinity>() / scale;
}

namespace {
double infinity_norm(const SparseMatrix& K) {  // max row sum of |K| (K symmetric: column sums)
  double norm = 0;
  for (int j = 0; j < K.outerSize(); ++j) {
    double sum = 0;
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) sum += std::abs(it.value());
    norm = std::max(norm, sum);
  }
  return norm;
}
}  // namespace

// The QP of the step at x_k (the increment's, shifted back to x: qp.x the new x), from
// `warm` if given; false (the QP's words in last_newton_failure_) if it fails.
bool ElasticContactSolver::solve_step_qp(const Eigen::VectorXd& b, const Eigen::VectorXd& f,
                                         const Eigen::VectorXd& x_k, const QpResult* warm, QpResult& qp) {
  try {
    solver_.set_operator(K_, C_free_);
    // In the increment δ = x − x_k: the QP's load is the residual itself. In the total
    // displacement (load K x_k − r) a thin structure's large K x_k left the residual
    // at 1e-7 (Turek–Hron's flag: digits lost to that cancellation).
    const Eigen::VectorXd c_delta = contact_.c_lb - C_free_ * x_k;
    qp = solver_.solve(b - f, c_delta, warm);
    qp.x += x_k;
  } catch (const QpError& e) {  // e.g. a tangent that is not positive definite: smaller load steps
    last_newton_failure_ = e.what();
    return false;
  }
  return true;
}

// The step from u (free dofs x_k) to the QP's qp.x, halved while it folds a triangle
// or does not reduce the residual below r_prev; the kMaxCuts-th halving is taken as
// it is (its residual infinite if it still folds one).
ElasticContactSolver::DampedStep ElasticContactSolver::damped_step(const Eigen::VectorXd& u, const Eigen::VectorXd& x_k,
                                                                   const QpResult& qp, const Eigen::VectorXd& b,
                                                                   double K_norm, double r_prev) {
  DampedStep step{u, Eigen::VectorXd(), INFINITY, 0};
  for (double s = 1;; s *= 0.5, ++step.cuts) {
    step.u(free_dofs_) = x_k + s * (qp.x - x_k);
    try {
      step.f = force(step.u);
      step.residual = equilibrium_residual(step.f, b, qp.alpha, step.u(free_dofs_), K_norm);
    } catch (const SolverFailure&) {  // a folded triangle: shorter
      step.residual = INFINITY;
    }
    if ((std::isfinite(step.residual) && step.residual < r_prev) || step.cuts == kMaxCuts) break;
  }
  return step;
}

Eigen::VectorXd ElasticContactSolver::force(const Eigen::VectorXd& u) const {
  Eigen::VectorXd f = assembler_->force(material_, u);
  if (has_inertia()) f += M_free_ * u(free_dofs_);
  return f;
}

// Newton from `state` for the load b_S; true (state: the solution) if converged.
bool ElasticContactSolver::newton(const Eigen::VectorXd& b_S, ContactSolution& state, NewtonReport& report) {
  report.history.clear();
  const Eigen::VectorXd b = b_S(free_dofs_);
  Eigen::VectorXd u = state.u, f;
  try {
    f = force(u);
  } catch (const SolverFailure& e) {  // a start (a warm state) with a folded triangle
    last_newton_failure_ = e.what();
    return false;
  }
  const bool warm_fits = state.qp.alpha.size() == contact_.c_lb.size();
  double r_prev = INFINITY;  // the start's multipliers belong to another load: never compared
  for (int step = 0; step < newton_max_steps; ++step) {
    assembler_->tangent(material_, u, K_);
    if (has_inertia()) K_ += M_free_;  // A_free_'s pattern holds M's: the sum keeps it
    const double K_norm = infinity_norm(K_);
    const Eigen::VectorXd x_k = u(free_dofs_);
    QpResult qp;
    if (!solve_step_qp(b, f, x_k, warm_fits || step > 0 ? &state.qp : nullptr, qp)) return false;
    ++report.steps;
    const DampedStep damped = damped_step(u, x_k, qp, b, K_norm, r_prev);
    report.cuts += damped.cuts;
    if (!std::isfinite(damped.residual)) return false;
    // The full step's size (a halved one says nothing of the error left).
    const double full_step = damped.cuts == 0 ? (qp.x - x_k).lpNorm<Eigen::Infinity>() : INFINITY;
    u = damped.u;
    f = damped.f;
    qp.x = u(free_dofs_);
    state.u = u;
    state.qp = std::move(qp);
    report.history.push_back(damped.residual);
    report.residual = damped.residual;
    if (damped.residual <= newton_tol || full_step <= newton_step_tol) return true;
    r_prev = damped.residual;
  }
  return false;
}

// Saint-Venant–Kirchhoff's energy stays finite as J → 0 and beyond: under strong
// compression Newton can converge to a state with folded triangles, a solution of
// the equations but not of any body. Said, never returned as an answer. With P2 the
// triangles checked are the nodal mesh's, the deformed shape the fluid and the
// outputs see.
void ElasticContactSolver::require_unfolded(const Eigen::VectorXd& u) const {
  int folded = 0;
  for (int t = 0; t < mesh_.num_triangles(); ++t)
    if (!(deformation_gradient(mesh_, t, u).determinant() > 0)) ++folded;
  if (folded)
    throw SolverFailure("the structure's equilibrium folds " + std::to_string(folded) +
                        " triangle(s) (det F <= 0): structure.model = \"" + material_name(material_.model) +
                        "\" is not valid under such compression; allowed: \"neo-hookean\" (its energy keeps det F > 0) or smaller loads");
}

ContactSolution ElasticContactSolver::solve_nonlinear(const Eigen::VectorXd& b_S, const ContactSolution* warm) {
  const ContactSolution start = warm && warm->u.size() == b_S.size() ? *warm : at_rest();
  NewtonReport report;
  last_newton_failure_.clear();
  // With inertia the load holds the last step's state (M's terms): scaled it is no
  // load path; a time step short enough is the remedy instead.
  const int max_load_steps = has_inertia() ? 1 : kMaxLoadSteps;
  for (int n = 1; n <= max_load_steps; n *= 2) {
    ContactSolution state = start;
    bool converged = true;
    for (int k = 1; k <= n && converged; ++k) converged = newton(b_S * (static_cast<double>(k) / n), state, report);
    if (converged) {
      report.load_steps = n;
      state.newton = report;
      require_unfolded(state.u);
      return state;
    }
  }
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "did not reach the relative residual %.3g in %d steps, with the load "
                "applied whole or in up to %d increments (last residual %.3g)", newton_tol, newton_max_steps,
                max_load_steps, report.residual);
  throw SolverFailure("Newton's method for the structure (structure.model = \"" +
                      std::string(material_name(material_.model)) + "\") " + numbers + "; the last attempt's residuals: " + history_text(report.history) +
                      (last_newton_failure_.empty() ? "" : "; the QP: " + last_newton_failure_));
}

}  // namespace fsi
