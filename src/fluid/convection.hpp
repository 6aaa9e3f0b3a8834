// The convective term ρ_F (v·∇)v of the steady Navier–Stokes equations (SPEC §10) on
// the mini space, the bubbles kept, linearised by Newton's method about a velocity w
// (a FluidSolution: P1 values and bubble coefficients):
//   Jacobian  ρ ∫ [(w·∇)δ + (δ·∇)w]·φ      (add: an unsymmetric ElementTerm)
//   load      ρ ∫ (w·∇)w·φ                 (add_load)
// so that K(w) v_new = F + ρ∫(w·∇)w·φ is the Newton step from w (the Stokes terms
// linear), its fixed point the discrete Navier–Stokes solution. The integrals are
// exact: w and φ are of degree 3 (the bubble), ∇ of degree 2, so the rule has degree 8.
// Picard's linearisation (Oseen's: ρ∫(w·∇)δ·φ, no load) shares the fixed point and
// converges from farther away, linearly: NewtonSolve falls back on it.
#pragma once

#include "fluid/mini_element.hpp"
#include "fluid/stokes_assembler.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

class NewtonConvection final : public ElementTerm {
 public:
  // `w` on `mesh` (every triangle's bubble); both referenced, not copied.
  NewtonConvection(double rho, const Mesh& mesh, const FluidSolution& w) : rho_(rho), mesh_(mesh), w_(w) {}

  void add(int t, const P1Triangle& T, MiniLocal& e) const override;
  void add_load(int t, const P1Triangle& T, ElementLoad& load) const override;
  bool symmetric() const override { return false; }
  // Picard's (Oseen's) linearisation instead of Newton's, until set back.
  void set_picard(bool picard) { picard_ = picard; }
  bool picard() const { return picard_; }

 private:
  double rho_;
  bool picard_ = false;
  const Mesh& mesh_;
  const FluidSolution& w_;
};

// The mini space's 8 velocity basis functions at barycentric λ of T: λ_a e_c (index
// 3c + a), then b e_d (index 6 + d); values and gradients (row c = ∇ of component c).
struct MiniVelocityBasis {
  std::array<Eigen::Vector2d, 8> value;
  std::array<Eigen::Matrix2d, 8> grad;
};
MiniVelocityBasis mini_velocity_basis(const P1Triangle& T, const Eigen::Vector3d& lambda);

}  // namespace fsi
