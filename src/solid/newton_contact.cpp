// Newton's method for a hyperelastic structure with frictionless contact (SPEC §11):
// at u_k, the QP in the total displacement x = u_{k+1} (free dofs)
//     min ½ xᵀ K_T(u_k) x − (K_T(u_k) x_k − r(u_k))ᵀ x   s.t.   C x ≥ c_lb,
// r(u) = f_int(u) − b, is the linearised equilibrium K_T (x − x_k) + r = Cᵀα with the
// contact's complementarity kept exactly in every step (the active set found by the
// QP, warm-started from the step before). The iteration stops when the nonlinear
// equilibrium's relative residual ‖f_int(u) − b − Cᵀα‖∞ / scale ≤ newton_tol.
// A step that folds a triangle or does not reduce that residual is halved (a
// feasible point: x_k and x_{k+1} both satisfy the linear constraint); if Newton
// still fails, the load is applied in 2, 4, ... 64 increments.
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {
namespace {

constexpr int kMaxCuts = 8;
constexpr int kMaxLoadSteps = 64;

}  // namespace

void ElasticContactSolver::set_material(const Material& material) {
  material_ = material;
  solver_.refactorise_often = material_.model != MaterialModel::linear;
  solver_.set_operator(A_free_, C_free_);
  if (material_.model != MaterialModel::linear) {
    assembler_ = std::make_unique<FreeDofAssembler>(mesh_, free_dofs_, A_free_);
    K_ = A_free_;
  }
}

// ‖f − b − Cᵀα‖∞ relative to the largest of the three terms (free dofs).
double ElasticContactSolver::equilibrium_residual(const Eigen::VectorXd& f, const Eigen::VectorXd& b,
                                                  const Eigen::VectorXd& alpha) const {
  const Eigen::VectorXd contact = alpha.size() ? Eigen::VectorXd(C_free_.transpose() * alpha)
                                               : Eigen::VectorXd::Zero(f.size());
  const double scale = std::max({b.lpNorm<Eigen::Infinity>(), f.lpNorm<Eigen::Infinity>(),
                                 contact.lpNorm<Eigen::Infinity>(), 1e-300});
  return (f - b - contact).lpNorm<Eigen::Infinity>() / scale;
}

// Newton from `state` for the load b_S; true (state: the solution) if converged.
bool ElasticContactSolver::newton(const Eigen::VectorXd& b_S, ContactSolution& state, NewtonReport& report) {
  report.history.clear();
  const Eigen::VectorXd b = b_S(free_dofs_);
  Eigen::VectorXd u = state.u, f;
  try {
    f = assembler_->force(material_, u);
  } catch (const SolverFailure& e) {  // a start (a warm state) with a folded triangle
    last_newton_failure_ = e.what();
    return false;
  }
  const bool warm_fits = state.qp.alpha.size() == contact_.c_lb.size();
  double r_prev = INFINITY;  // the start's multipliers belong to another load: never compared
  for (int step = 0; step < newton_max_steps; ++step) {
    assembler_->tangent(material_, u, K_);
    const Eigen::VectorXd x_k = u(free_dofs_);
    QpResult qp;
    try {
      solver_.set_operator(K_, C_free_);
      qp = solver_.solve(K_ * x_k - (f - b), contact_.c_lb, warm_fits || step > 0 ? &state.qp : nullptr);
    } catch (const QpError& e) {  // e.g. a tangent that is not positive definite: smaller load steps
      last_newton_failure_ = e.what();
      return false;
    }
    ++report.steps;
    double s = 1, r_new = INFINITY;
    Eigen::VectorXd u_new = u, f_new;
    for (int cut = 0; cut <= kMaxCuts; ++cut, s *= 0.5) {
      u_new(free_dofs_) = x_k + s * (qp.x - x_k);
      try {
        f_new = assembler_->force(material_, u_new);
        r_new = equilibrium_residual(f_new, b, qp.alpha);
      } catch (const SolverFailure&) {  // a folded triangle: shorter
        r_new = INFINITY;
      }
      if (std::isfinite(r_new) && r_new < r_prev) break;
      if (cut > 0) ++report.cuts;
    }
    if (!std::isfinite(r_new)) return false;
    u = u_new;
    f = f_new;
    qp.x = u(free_dofs_);
    state.u = u;
    state.qp = std::move(qp);
    report.history.push_back(r_new);
    report.residual = r_new;
    if (r_new <= newton_tol) return true;
    r_prev = r_new;
  }
  return false;
}

ContactSolution ElasticContactSolver::solve_nonlinear(const Eigen::VectorXd& b_S, const ContactSolution* warm) {
  const ContactSolution start = warm && warm->u.size() == b_S.size() ? *warm : at_rest();
  NewtonReport report;
  last_newton_failure_.clear();
  for (int n = 1; n <= kMaxLoadSteps; n *= 2) {
    ContactSolution state = start;
    bool converged = true;
    for (int k = 1; k <= n && converged; ++k) converged = newton(b_S * (static_cast<double>(k) / n), state, report);
    if (converged) {
      report.load_steps = n;
      state.newton = report;
      return state;
    }
  }
  throw SolverFailure("Newton's method for the structure (structure.model = \"" +
                      std::string(material_.model == MaterialModel::neo_hookean ? "neo-hookean" : "saint-venant-kirchhoff") +
                      "\") did not reach the relative residual " + std::to_string(newton_tol) + " in " +
                      std::to_string(newton_max_steps) + " steps, with the load applied whole or in up to " +
                      std::to_string(kMaxLoadSteps) + " increments (last residual " +
                      std::to_string(report.residual) + ")" +
                      (last_newton_failure_.empty() ? "" : "; the QP: " + last_newton_failure_));
}

}  // namespace fsi
