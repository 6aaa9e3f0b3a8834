#include "fluid/penalised_stokes.hpp"

#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"

namespace fsi {

PenalisedStokes::PenalisedStokes(const Mesh& mesh, double mu, double eps, const VectorField& f,
                                 const FluidBoundaryConditions& bc, const std::string& solver,
                                 FluidFactorization factorization, double far_factor_budget_mb)
    : assembler_(mesh, mu, f, bc, factorization == FluidFactorization::schur),
      solver_(solver),
      chi_(Eigen::VectorXd::Zero(mesh.num_triangles())),
      eps_(eps) {
  set_factorization(factorization, far_factor_budget_mb);
}

void PenalisedStokes::set_factorization(FluidFactorization f, double far_factor_budget_mb) {
  if (solved_once_) throw std::logic_error("PenalisedStokes::set_factorization after a solve");
  factorization_ = f;
  newton_ = nullptr;
  if (f == FluidFactorization::schur)
    strategy_ = std::make_unique<SubstructuredSolve>(assembler_, solver_, timing_, solution_, far_factor_budget_mb);
  else
    strategy_ = std::make_unique<WholeSolve>(assembler_, solver_, timing_, solution_, linear_options_);
}

void PenalisedStokes::set_linear_solver(const std::string& solver, const LinearSolverOptions& options) {
  if (solved_once_ || newton_) throw std::logic_error("PenalisedStokes::set_linear_solver after a solve or Newton's set-up");
  solver_ = solver;
  linear_options_ = options;
  set_factorization(FluidFactorization::whole, INFINITY);
}

void PenalisedStokes::set_viscous_form(ViscousForm form) {
  change_problem([&] { assembler_.set_viscous_form(form); });
}

void PenalisedStokes::set_navier_stokes(const NewtonOptions& options) {
  if (solved_once_) throw std::logic_error("PenalisedStokes::set_navier_stokes after a solve");
  if (factorization_ != FluidFactorization::whole)
    throw std::invalid_argument("Navier–Stokes is solved on the whole factorisation only");
  auto newton = std::make_unique<NewtonSolve>(assembler_, solver_, timing_, solution_, options, linear_options_);
  newton_ = newton.get();
  strategy_ = std::move(newton);
  ++version_;
}

void PenalisedStokes::set_chi(const Eigen::VectorXd& chi) {
  if (chi.size() != chi_.size()) throw std::invalid_argument("set_chi: one value per triangle");
  if (chi != chi_) {
    chi_ = chi;
    ++version_;
  }
}

void PenalisedStokes::set_eps(double eps) {
  if (eps != eps_) {
    strategy_->settle();  // a deferred expansion's bubbles need the old ε
    eps_ = eps;
    ++version_;
  }
}

// A change of the operator or of the loads beyond χ and ε: a deferred expansion is
// finished first (its bubbles belong to the old problem), the substructured solve's
// region dropped (its far field condensed the old operator and load), a new version.
template <class Change>
void PenalisedStokes::change_problem(Change&& change) {
  strategy_->settle();
  change();
  strategy_->load_changed();
  ++version_;
}

void PenalisedStokes::set_body_force(const VectorField& f) {
  change_problem([&] { assembler_.set_body_force(f); });
}

void PenalisedStokes::set_boundary_data(const FluidBoundaryConditions& bc) {
  change_problem([&] { assembler_.set_boundary_data(bc); });
}

void PenalisedStokes::add_term(std::shared_ptr<const ElementTerm> term) {
  change_problem([&] { assembler_.add_term(std::move(term)); });
}

void PenalisedStokes::terms_changed() {
  change_problem([&] { assembler_.forget_assembly(); });
}

void PenalisedStokes::near_terms_changed() {
  assembler_.forget_assembly();
  strategy_->near_changed();
  ++version_;
}

void PenalisedStokes::reset() {
  solved_once_ = false;
  ++version_;
  chi_.setZero();
  timing_ = FluidTiming{};
  strategy_->new_run();
}

const FluidSolution& PenalisedStokes::solve(SampledTriangles sampled) {
  if (solved_version_ == version_) {
    ++timing_.reused;
    return solution(sampled);
  }
  if (!assembler_.symmetric() && strategy_->needs_symmetry())
    throw SolverFailure("the fluid's operator is unsymmetric and " + strategy_->name() +
                        " factors symmetric systems only; allowed: the whole factorisation with umfpack, "
                        "umfpack-metis or eigen-lu");
  strategy_->solve(chi_, eps_, sampled);
  solved_once_ = true;
  solved_version_ = version_;
  solved_chi_ = chi_;
  return solution_;
}

const FluidSolution& PenalisedStokes::solution(SampledTriangles sampled) {
  if (!solved_once_) throw std::logic_error("PenalisedStokes::solution before a successful solve");
  strategy_->extend(sampled);
  return solution_;
}

}  // namespace fsi
