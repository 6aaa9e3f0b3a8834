// The fluid's force on a wall by the residual (volume) method (SPEC §10 "Forces"):
// the weak residual of the momentum equation (25), without penalty, tested with the
// P1 velocity basis functions φ_i e_c of the wall's vertices,
//     R_{i,c} = ∫_D 2μ ε(v_h):ε(φ_i e_c) − ∫_D p_h div(φ_i e_c) − ∫_D f·φ_i e_c
// (+ ρ ∫_D (v_h·∇)v_h·φ_i e_c for Navier–Stokes; μ∇v_h:∇φ_i e_c in the gradient form).
// For the exact solution this is ∫_{∂D} σ(v,p) n · φ_i e_c (n out of the fluid): the
// traction the fluid receives from the wall, so −R is the fluid's force on it, node by
// node. Much more accurate than integrating σ(v_h,p_h) n along the wall (its
// resultant converges at the rate of the energy error squared), and it needs no
// normal. The bubbles enter through the condensed element: their own equations hold
// exactly, so testing with φ_i e_c alone is the same as with the full mini element.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "fluid/penalised_stokes.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

// The momentum equation's operator: μ, the viscous term's form, and ρ (0: Stokes).
// For Navier–Stokes the residual is the condensed Newton element at v_h (Jacobian
// times v_h minus its load): the full residual's vertex rows, the bubble rows being
// solved to Newton's tolerance.
struct MomentumModel {
  double mu;
  ViscousForm form = ViscousForm::symmetric;
  double rho = 0;
  // An unsteady step's ρ∂v/∂t (SPEC §12: FluidTimeDerivative with that step's
  // history, FluidTimeStepper::last_step_inertia), part of the residual; null: steady.
  const ElementTerm* inertia = nullptr;
};

// Column k: (R_{i,1}, R_{i,2}) for i = vertices[k]. Only the triangles around these
// vertices are visited. `kappa`: the penalty χ/ε per triangle the solution was
// computed with, (1/ε)∫χ v·φ_i e_c then part of R (the whole discrete equation's
// residual); empty: χ = 0. A vertex on a traction boundary would also carry that
// traction.
Eigen::Matrix2Xd momentum_residual(const Mesh& mesh, const MomentumModel& model,
                                   const std::function<Point(const Point&)>& f,
                                   const FluidSolution& solution, const std::vector<int>& vertices,
                                   const Eigen::VectorXd& kappa = {});
inline Eigen::Matrix2Xd momentum_residual(const Mesh& mesh, double mu, const std::function<Point(const Point&)>& f,
                                          const FluidSolution& solution, const std::vector<int>& vertices,
                                          const Eigen::VectorXd& kappa = {}) {
  return momentum_residual(mesh, MomentumModel{mu}, f, solution, vertices, kappa);
}

// The fluid's force on the hole labelled `label` (N per metre of depth: SPEC §10
// "Forces"): −Σ R over its vertices, the residual of a solution computed with the
// penalty `kappa` = χ/ε per triangle (empty or zero: no penalty) and the body force f_F.
Point hole_force(const Mesh& mesh, const MomentumModel& model, const std::function<Point(const Point&)>& f_F,
                 const FluidSolution& s, int label, const Eigen::VectorXd& kappa);
// The same for a constant f_F.
Point hole_force(const Mesh& mesh, const MomentumModel& model, const Point& f_F, const FluidSolution& s, int label,
                 const Eigen::VectorXd& kappa);
inline Point hole_force(const Mesh& mesh, double mu, const Point& f_F, const FluidSolution& s, int label,
                        const Eigen::VectorXd& kappa) {
  return hole_force(mesh, MomentumModel{mu}, f_F, s, label, kappa);
}

}  // namespace fsi
