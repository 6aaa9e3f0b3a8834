// The fluid step of the body-fitted method (fluid.method = "body-fitted"), steps 2–3 of
// §6 with the fluid domain made to fit the structure: for a displacement u, the mesh of
// D \ φ(Ω_S0) with the deformed outline's points as vertices, steady Stokes on it
// without penalty (v = 0 on Γ_u: the structure at rest, the paper's conditions on
// Σ1…Σ5), and the fluid's load on the structure by the residual method, node to node
// (body_fitted_force.hpp). An independent check of the fictitious domain of §3–§4:
// nothing of χ, ε or eq. (33) is used. It cannot mesh a closed gap: a structure near
// an obstacle (any hole of D: [obstacle]'s disk, or each of [[obstacles]]) or the box
// is refused (SolverFailure).
//
// Remeshing: Gmsh's mesh is a discontinuous function of the outline (its triangle count
// changes by tens from one pass to the next), which puts a noise floor under the
// fixed point's increments (measured on the no-contact §7.2 variant at hF = 0.005:
// increments stall between 3e-8 and 5e-7 for 80 passes, Aitken's ω at its floor).
// So a pass remeshes only if the outline moved more than move_limit·hF since the last
// mesh was made, or moving that mesh would spoil it; otherwise that mesh is moved with
// the outline (fem/harmonic_extension.hpp): the same triangles, a smooth function of u.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "coupling/body_fitted_force.hpp"
#include "fem/harmonic_extension.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fluid/stokes_residual.hpp"
#include "mesh/gmsh_io.hpp"

namespace fsi {

struct BodyFittedFluidParams {
  FluidGeometry box;  // D: the box, its holes (the disk, or box.holes), and h = hF
  double mu = 0;
  VectorField f;  // f_F
  // SPEC §10: the viscous form, and ρ > 0 for Navier–Stokes, solved by Newton's
  // method from rest on each pass's mesh (a new mesh has no last solution to start from).
  ViscousForm form = ViscousForm::symmetric;
  double rho = 0;
  NewtonOptions newton;
  // The conditions on Σ1…Σ5 for a mesh of D (the run layer's, by label); v = 0 on
  // Gamma_u is added here.
  std::function<FluidBoundaryConditions(const Mesh&)> boundary_conditions;
  PressureNormal normal = PressureNormal::reference;
  // A gap to an obstacle or to the box's other sides below this many hF is refused:
  // the triangles there would be much smaller than hF, and the configuration is
  // about to touch, which this method cannot follow.
  double min_gap = 0.25;
  // Remesh when an outline point moved more than this many hF since the last mesh,
  // or the moved mesh's smallest angle would fall below half of that mesh's.
  double move_limit = 0.25;
};

struct BodyFittedSolve {
  std::unique_ptr<Mesh> mesh;  // D \ φ(Ω_S0)
  FluidSolution solution;
  std::vector<int> outline_nodes;  // the fluid vertex of each outline point
  Eigen::VectorXd load;            // the fluid's load on the structure, 2nv
  double gap = INFINITY;           // from φ(outline) to the holes and the box's other sides, m
  bool remeshed = false;           // a new Gmsh mesh (else the last one moved)
  int unknowns = 0;
  double t_mesh = 0, t_fluid = 0, t_transfer = 0;
};

class BodyFittedFluid {
 public:
  // `reference`: the structure's mesh, its clamped side labelled `clamped_label` on
  // x = 0 (Σ1); throws MeshError if that side has a vertex off x = 0 or the boundary
  // off it is not one chain (a user's structure.mesh).
  BodyFittedFluid(BodyFittedFluidParams params, const Mesh& reference, int clamped_label);

  // Throws SolverFailure if the gap is too small, or meshing or the solve fails.
  // Not const: it keeps the last Gmsh mesh, to move it for the next u.
  BodyFittedSolve solve(const Eigen::VectorXd& u);

  const std::vector<int>& outline() const { return outline_; }
  const BodyFittedFluidParams& params() const { return p_; }

 private:
  std::vector<Point> deformed_outline(const Eigen::VectorXd& u) const;
  void check_gap(const std::vector<Point>& x, double& gap) const;
  Mesh fluid_mesh(const std::vector<Point>& x, BodyFittedSolve& step);
  Mesh remesh(const std::vector<Point>& x, BodyFittedSolve& step);

  BodyFittedFluidParams p_;
  const Mesh& reference_;
  std::vector<int> outline_;  // reference vertices of Γ_u, in order
  // The last Gmsh mesh: the outline it was made for, its nodes there, its smallest
  // angle, and its motion (built when first needed).
  std::unique_ptr<Mesh> base_;
  std::vector<Point> base_outline_;
  std::vector<int> base_nodes_;
  double base_angle_ = 0;
  std::unique_ptr<HarmonicExtension> motion_;
};

}  // namespace fsi
