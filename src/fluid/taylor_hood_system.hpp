// The Taylor–Hood element (velocity P2, pressure P1, both isoparametric on curved
// holes: fem/iso_p2.hpp) for the fluid's momentum and continuity equations on the
// fixed mesh (SPEC §3, §10, §12: fluid.element = "taylor-hood"),
//     ∫ m v·w + a(v, w) + ρ∫(v·∇)v·w − ∫ p div w − ∫ f·w − ∫ h_hist·w − ∫_Σ h·w = 0,
//     −∫ q div v = 0,
// with a(·,·) the viscous form (symmetric 2μ ε:ε or gradient μ∇:∇), m = ρα/Δt + κ_T
// (the time derivative's and the penalty χ_T/ε's mass) and h_hist the BDF history's
// load. Inf-sup stable without bubbles, and second order in H¹ where the mini element
// is first: the accuracy per unknown the DFG benchmarks need.
//
// It assembles the residual R(U) on every dof and Newton's Jacobian ∂R/∂U on the free
// ones (pattern built once, values written in place through per-element slots, as
// StokesAssembler does). Unknowns U = [v1 at the P2 nodes, v2 at them, p at the
// vertices]; the prescribed velocities are part of U.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "fem/iso_p2.hpp"
#include "fem/vector_p1.hpp"  // VectorField
#include "fluid/stokes_assembler.hpp"  // FluidBoundaryConditions
#include "fluid/viscous_form.hpp"

namespace fsi {

struct TaylorHoodModel {
  double mu = 1;
  ViscousForm form = ViscousForm::symmetric;
  double rho = 0;  // ρ_F in the convection term; 0: Stokes
};

class TaylorHoodSystem {
 public:
  // Refers to `geometry`, which must outlive it. The Dirichlet labels of `bc` fix the
  // free dofs for good (set_data may change their values only).
  TaylorHoodSystem(const IsoP2Geometry& geometry, const TaylorHoodModel& model, const VectorField& f,
                   const FluidBoundaryConditions& bc);

  const IsoP2Geometry& geometry() const { return geometry_; }
  const TaylorHoodModel& model() const { return model_; }
  int velocity_nodes() const { return nn_; }
  int dofs() const { return 2 * nn_ + nv_; }
  int unknowns() const { return static_cast<int>(free_.size()); }
  // Dof of component c (0, 1) at P2 node i, and of the pressure at vertex a.
  int velocity_dof(int c, int i) const { return c * nn_ + i; }
  int pressure_dof(int a) const { return 2 * nn_ + a; }

  // New body force and boundary values (data in time, SPEC §12); std::invalid_argument
  // if other dofs would be prescribed.
  void set_data(const VectorField& f, const FluidBoundaryConditions& bc);
  // The time derivative: the mass coefficient ρα/Δt and the history ρ(β₁vⁿ + β₂vⁿ⁻¹)/Δt
  // as a P2 velocity (2·nodes; the rest of a dof vector is ignored). Zero: steady.
  void set_inertia(double mass, const Eigen::VectorXd& history);
  double mass() const { return mass_; }
  // Picard's (Oseen's) linearisation in the Jacobian: ρ(w·∇)δ only, without (δ·∇)w
  // (Newton's fallback where no damping helps). The residual is the same.
  void set_picard(bool picard) { picard_ = picard; }
  // The penalty κ_T = χ_T/ε per triangle (empty: none).
  void set_penalty(const Eigen::VectorXd& kappa) { kappa_ = kappa, ++revision_; }
  // Changes whenever the Jacobian at a given U does (a new mass coefficient, a new
  // penalty): factors of an older revision do not belong to this operator.
  long revision() const { return revision_; }

  // U with its prescribed dofs set to the boundary values.
  void impose(Eigen::VectorXd& U) const;
  // The residual R(U) on every dof; with `jacobian`, also ∂R/∂U on the free dofs.
  void assemble(const Eigen::VectorXd& U, bool jacobian, Eigen::VectorXd& R);
  const Eigen::SparseMatrix<double>& jacobian() const { return J_; }
  // The free part of a dof vector, and a free part added back into one.
  Eigen::VectorXd free_part(const Eigen::VectorXd& full) const;
  // Per free dof, 1 for a pressure's (the saddle point's second field).
  std::vector<char> pressure_unknowns() const;
  void add_free(const Eigen::VectorXd& part, double scale, Eigen::VectorXd& full) const;

 private:
  using Local = Eigen::Matrix<double, 15, 15>;
  using LocalVector = Eigen::Matrix<double, 15, 1>;
  std::array<int, 15> local_dofs(int t) const;
  void element(int t, const Eigen::VectorXd& U, bool jacobian, Local& K, LocalVector& r) const;
  void build_pattern();
  void traction_residual(Eigen::VectorXd& R) const;

  const IsoP2Geometry& geometry_;
  TaylorHoodModel model_;
  int nn_, nv_;
  std::vector<Point> f_at_;             // body force at every quadrature point
  FluidBoundaryConditions bc_;
  Eigen::VectorXd prescribed_;          // boundary values at the prescribed dofs
  std::vector<int> free_index_, free_;  // dof → free index (−1: prescribed); free → dof
  double mass_ = 0;
  long revision_ = 0;
  bool picard_ = false;
  Eigen::VectorXd history_;
  Eigen::VectorXd kappa_;
  Eigen::SparseMatrix<double> J_;
  std::vector<int> slot_;               // 225 per triangle: position in J_'s values, −1 if not free–free
};

}  // namespace fsi
