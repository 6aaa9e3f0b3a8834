#include "fluid/fluid_time_stepper.hpp"

#include <stdexcept>

namespace fsi {

FluidSolution fluid_at_rest(const Mesh& mesh) {
  FluidSolution s;
  s.v1 = Eigen::VectorXd::Zero(mesh.num_vertices());
  s.v2 = Eigen::VectorXd::Zero(mesh.num_vertices());
  s.p = Eigen::VectorXd::Zero(mesh.num_vertices());
  s.bubble = Eigen::Matrix2Xd::Zero(2, mesh.num_triangles());
  return s;
}

FluidTimeStepper::FluidTimeStepper(PenalisedStokes& fluid, double rho, TimeScheme scheme, double dt,
                                   const FluidSolution& initial, double t0)
    : fluid_(fluid),
      scheme_(scheme),
      dt_(dt),
      t0_(t0),
      derivative_(std::make_shared<FluidTimeDerivative>(rho, fluid.mesh())),
      v_n_(std::make_unique<FluidSolution>(initial)),
      v_nm1_(std::make_unique<FluidSolution>(initial)),
      spare_(std::make_unique<FluidSolution>()) {
  if (!(dt > 0)) throw std::invalid_argument("FluidTimeStepper: the time step must be positive");
  v_n_->exact_on = v_nm1_->exact_on = nullptr;
  fluid_.add_term(derivative_);
}

const FluidSolution& FluidTimeStepper::step(const std::function<void(double)>& data) {
  begin(data);
  solve();
  accept();
  return *v_n_;
}

// The convecting velocity of a semi-implicit step: 2vⁿ − vⁿ⁻¹ (second order, with
// BDF2), or vⁿ.
FluidSolution FluidTimeStepper::extrapolated(bool second_order) const {
  if (!second_order) return *v_n_;
  FluidSolution w;
  w.v1 = 2 * v_n_->v1 - v_nm1_->v1, w.v2 = 2 * v_n_->v2 - v_nm1_->v2;
  w.p = 2 * v_n_->p - v_nm1_->p, w.bubble = 2 * v_n_->bubble - v_nm1_->bubble;
  return w;
}

void FluidTimeStepper::begin(const std::function<void(double)>& data) {
  if (data) data(time() + dt_);
  const BdfWeights w = bdf_weights(scheme_, steps_);
  derivative_->set_step(dt_, w, *v_n_, w.beta2 != 0 ? v_nm1_.get() : nullptr);
  if (fluid_.semi_implicit()) fluid_.linearise_about(extrapolated(w.beta2 != 0));
  fluid_.terms_changed();
  solved_ = false;
}

const FluidSolution& FluidTimeStepper::solve(SampledTriangles sampled) {
  *spare_ = fluid_.solve(sampled);
  solved_ = true;
  return *spare_;
}

void FluidTimeStepper::accept() {
  if (!solved_) throw std::logic_error("FluidTimeStepper::accept before a solve of the step");
  if (spare_->exact_on) *spare_ = fluid_.solution();  // the far field's expansion: one solve
  spare_->exact_on = nullptr;
  std::swap(v_nm1_, spare_);  // (v^n, v^{n−1}, spare) ← (new, v^n, v^{n−1})
  std::swap(v_n_, v_nm1_);
  ++steps_;
  solved_ = false;
  stepped_ = true;
}

void FluidTimeStepper::restore(int steps, const FluidSolution& v_n, const FluidSolution& v_nm1) {
  if (steps < 0) throw std::invalid_argument("FluidTimeStepper::restore: a negative step count");
  *v_n_ = v_n, *v_nm1_ = v_nm1;
  v_n_->exact_on = v_nm1_->exact_on = nullptr;
  steps_ = steps;
  solved_ = stepped_ = false;
}

}  // namespace fsi
