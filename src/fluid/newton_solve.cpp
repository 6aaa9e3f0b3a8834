#include "fluid/newton_solve.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/timer.hpp"

namespace fsi {
namespace {

void set_zero(FluidSolution& s) {
  s.v1.setZero(), s.v2.setZero(), s.p.setZero(), s.bubble.setZero();
  s.exact_on = nullptr;
}

}  // namespace

NewtonSolve::NewtonSolve(StokesAssembler& assembler, const std::string& solver, FluidTiming& timing,
                         FluidSolution& out, const NewtonOptions& options, const LinearSolverOptions& linear)
    : assembler_(assembler), whole_(assembler, solver, timing, out, linear), timing_(timing), out_(out), options_(options) {
  assembler_.prescribed_fields(w_);
  set_zero(w_);
  convection_ = std::make_shared<NewtonConvection>(options.rho, assembler.mesh(), w_);
  assembler_.add_term(convection_);
}

void NewtonSolve::new_run() {
  whole_.new_run();
  set_zero(w_);
  started_ = false;
  scale_ = 0;
  report_ = FluidNewtonReport{};
}

void NewtonSolve::start_from(const FluidSolution& last) {
  w_ = last;
  w_.exact_on = nullptr;
  started_ = true;
}

// Assembles K(w) and b(w) in Newton's form (the next step reuses them) and returns
// ‖K(w) x_w − b(w)‖ and its scale max(‖b(0)‖, ‖b(w)‖): the data, or the inertia's
// share of the right-hand side where it is the larger (round-off grows with it).
// At rest (w = 0) this assembly is b(0)'s own: the scale is read from it instead of
// being assembled apart.
NewtonSolve::Residual NewtonSolve::residual(const Eigen::VectorXd& chi, double eps, bool at_rest) {
  const double b0 = at_rest ? 0.0 : scale(chi, eps);
  const Stopwatch clock;
  convection_->set_picard(false);
  whole_.prepare();  // on several ranks, each assembles its own rows: the norms are over all
  assembler_.forget_assembly();
  assembler_.assemble(chi, eps);
  if (at_rest && !(scale_ > 0)) scale_ = whole_.norm(assembler_.rhs());
  const Residual r{whole_.norm(assembler_.matrix() * assembler_.reduced(w_) - assembler_.rhs()),
                   std::max(at_rest ? scale_ : b0, whole_.norm(assembler_.rhs()))};
  timing_.assembly += clock.elapsed();
  return r;
}

// ‖b(0)‖: the right-hand side with the convection's load at v = 0 (the Stokes data:
// body force, prescribed velocities, tractions).
double NewtonSolve::scale(const Eigen::VectorXd& chi, double eps) {
  if (scale_ > 0) return scale_;
  const Stopwatch clock;
  const FluidSolution kept = w_;
  set_zero(w_);
  whole_.prepare();
  assembler_.forget_assembly();
  assembler_.assemble(chi, eps);
  scale_ = whole_.norm(assembler_.rhs());
  w_ = kept;
  timing_.assembly += clock.elapsed();
  return scale_;
}

namespace {

// out = a + λ (b − a), every field (the bubbles too).
void blend(const FluidSolution& a, const FluidSolution& b, double lambda, FluidSolution& out) {
  out.v1 = a.v1 + lambda * (b.v1 - a.v1);
  out.v2 = a.v2 + lambda * (b.v2 - a.v2);
  out.p = a.p + lambda * (b.p - a.p);
  out.bubble = a.bubble + lambda * (b.bubble - a.bubble);
  out.exact_on = nullptr;
}

}  // namespace

// One Newton step from w_ (whose Newton assembly residual() left), damped by
// halving until the residual falls (Armijo's test, the usual globalisation): from
// rest at Re ~ 100 the full step overshoots. If even a sixteenth of it does not
// help, a Picard step instead. Returns the residual at the new w_, assembled.
NewtonSolve::Residual NewtonSolve::step(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled,
                                        const Residual& r) {
  const FluidSolution from = w_;
  whole_.solve(chi, eps, sampled);
  const FluidSolution full = out_;
  ++report_.total_steps;
  for (double lambda = 1; lambda >= 1.0 / 16; lambda /= 2) {
    blend(from, full, lambda, w_);
    const Residual next = residual(chi, eps);
    if (next.norm <= (1 - 1e-4 * lambda) * r.norm) {
      ++report_.steps;
      if (lambda < 1) ++report_.damped;
      return next;
    }
  }
  ++report_.rejected;
  w_ = from;
  convection_->set_picard(true);
  assembler_.forget_assembly();
  whole_.solve(chi, eps, sampled);
  w_ = out_;
  ++report_.picard_steps, ++report_.total_picard_steps;
  return residual(chi, eps);
}

void NewtonSolve::linearise_about(FluidSolution w) {
  about_ = std::move(w);
  about_->exact_on = nullptr;
}

void NewtonSolve::solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) {
  if (options_.semi_implicit && about_) return solve_oseen(chi, eps, sampled);
  if (!started_) set_zero(w_);  // the first step is the Stokes solution
  report_.residuals.clear();
  report_.steps = report_.picard_steps = report_.rejected = report_.damped = 0;
  Residual r = residual(chi, eps, !started_);
  for (int k = 0;; ++k) {
    report_.residuals.push_back(r.relative());
    if (r.relative() <= options_.tol) break;
    if (k == options_.max_steps) fail();
    r = step(chi, eps, sampled, r);
  }
  convection_->set_picard(false);
  out_ = w_;
  started_ = true;
  ++report_.solves;
  report_.max_final_residual = std::max(report_.max_final_residual, report_.residuals.back());
}

// time.convection = "semi-implicit": ρ(w·∇)v with w the step's extrapolated velocity,
// one linear solve (the convection's Picard form, NewtonConvection::set_picard).
void NewtonSolve::solve_oseen(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) {
  w_ = *about_;
  convection_->set_picard(true);
  assembler_.forget_assembly();
  whole_.solve(chi, eps, sampled);
  convection_->set_picard(false);
  w_ = out_;
  started_ = true;
  report_.residuals.clear();
  report_.steps = report_.rejected = report_.damped = 0;
  report_.picard_steps = 1;
  ++report_.total_picard_steps, ++report_.solves;
}

void NewtonSolve::fail() const {
  std::string history;
  for (double r : report_.residuals) history += (history.empty() ? "" : ", ") + approx(r, 2);
  throw SolverFailure("Newton's method did not reach fluid.newton_tol = " + shortest(options_.tol) + " in " +
                      std::to_string(options_.max_steps) + " steps (" + std::to_string(report_.picard_steps) +
                      " of them Picard's, " + std::to_string(report_.damped) + " damped); relative residuals " + history +
                      ": a steady flow may not exist at this Reynolds number (lower fluid.rho or the inflow, or "
                      "raise fluid.newton_max_steps)");
}

}  // namespace fsi
