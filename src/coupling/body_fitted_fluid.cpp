#include "coupling/body_fitted_fluid.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "fluid/stokes_residual.hpp"
#include "mesh/polygon.hpp"
#include "mesh/structure_outline.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {
namespace {

// The distance from the deformed outline (the polygon of φ(Ω_S0), closed along x = 0)
// to one hole of D: to a disk's circle, centre distance − r; to a polygon, the
// distance between the two regions (0 if they meet).
double distance_to_hole(const std::vector<Point>& x, const FluidHole& hole) {
  if (!hole.corners.empty()) return polygon_distance(x, hole.corners);
  const Point centre(hole.x0, hole.y0);
  double d = INFINITY;
  for (std::size_t k = 0; k + 1 < x.size(); ++k)
    d = std::min(d, distance_to_segment(centre, x[k], x[k + 1]) - hole.r);
  return d;
}

}  // namespace

BodyFittedFluid::BodyFittedFluid(BodyFittedFluidParams params, const Mesh& reference,
                                 int clamped_label)
    : p_(std::move(params)),
      reference_(reference),
      outline_(structure_outline(reference, clamped_label)) {
  // The fluid's outer boundary runs down Σ1 (x = 0) to one end of the outline and on
  // from the other: both ends, and the clamped side between them, must lie on it.
  const double tolerance = 1e-9 * std::max({p_.box.L1, p_.box.H1 + p_.box.H2, 1e-300});
  for (int v : reference.vertices_on(clamped_label))
    if (!(std::abs(reference.vertices[v].x()) <= tolerance))
      throw MeshError(
          "the structure's clamped side " + reference.label_names[clamped_label] +
          " has a vertex off x = 0 (Sigma_1), at x = " + std::to_string(reference.vertices[v].x()) +
          "; the body-fitted fluid mesh closes the structure's outline along x = 0");
}

std::vector<Point> BodyFittedFluid::deformed_outline(const Eigen::VectorXd& u) const {
  const int nv = reference_.num_vertices();
  std::vector<Point> x;
  x.reserve(outline_.size());
  for (int v : outline_)
    x.push_back(reference_.vertices[v] + Point(u[dof(v, 0, nv)], u[dof(v, 1, nv)]));
  return x;
}

// The smallest distance from φ(Γ_u) to what it must not reach: every hole of D (Σ5:
// the obstacle's circle, or each of [[obstacles]], SPEC §9) and the sides Σ2, Σ3, Σ4
// (Σ1 holds the clamp: the outline starts and ends there). Below min_gap·hF the fluid
// between would be thinner than its triangles, and the structure is about to touch:
// the body-fitted method does not model contact, even with contact.gap = "normal".
void BodyFittedFluid::check_gap(const std::vector<Point>& x, double& gap) const {
  const FluidGeometry& b = p_.box;
  gap = INFINITY;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const bool end = k == 0 || k + 1 == x.size();
    if (!end && !(x[k].x() > 0))
      throw SolverFailure(
          "the deformed structure crosses the wall x = 0 (Sigma_1) at a vertex; fluid.method = "
          "\"body-fitted\" cannot mesh the fluid around it");
    gap = std::min({gap, x[k].y() + b.H2, b.L1 - x[k].x(), b.H1 - x[k].y()});
  }
  std::string nearest = "the box";
  const std::vector<FluidHole> holes =
      b.holes ? *b.holes : std::vector<FluidHole>{{b.x0, b.y0, b.r}};
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const double d = distance_to_hole(x, holes[i]);
    if (d < gap)
      gap = d, nearest = b.holes ? "obstacles[" + std::to_string(i + 1) + "]" : "the obstacle";
  }
  if (!(gap >= p_.min_gap * b.h)) {
    char text[600];
    std::snprintf(text, sizeof text,
                  "the deformed structure comes within %.3g m of %s (below %.2g hF = %.3g m): "
                  "contact cannot be body-fitted; fluid.method = \"body-fitted\" is a check for "
                  "configurations without contact, whose structure stays %.2g hF away from every "
                  "obstacle and side (use \"penalised\")",
                  gap, nearest.c_str(), p_.min_gap, p_.min_gap * b.h, p_.min_gap);
    throw SolverFailure(text);
  }
}

Mesh BodyFittedFluid::remesh(const std::vector<Point>& x, BodyFittedSolve& step) {
  try {
    base_ = std::make_unique<Mesh>(generate_fluid_mesh_around({p_.box, x}));
    const double tolerance = 1e-9 * std::max({p_.box.L1, p_.box.H1 + p_.box.H2, 1e-300});
    base_nodes_ = match_vertices(*base_, base_->label("Gamma_u"), x, tolerance);
  } catch (const MeshError& e) {
    base_.reset();
    throw SolverFailure(std::string("meshing the fluid around the deformed structure failed: ") +
                        e.what());
  }
  base_outline_ = x;
  base_angle_ = min_angle_deg(*base_);
  motion_.reset();
  step.remeshed = true;
  step.outline_nodes = base_nodes_;
  return *base_;
}

// D \ φ(Ω_S0) with the outline's points as vertices: the last mesh moved with the
// outline if it moved little since that mesh was made, else a new one.
Mesh BodyFittedFluid::fluid_mesh(const std::vector<Point>& x, BodyFittedSolve& step) {
  if (!base_) return remesh(x, step);
  double move = 0;
  for (std::size_t k = 0; k < x.size(); ++k)
    move = std::max(move, (x[k] - base_outline_[k]).norm());
  if (move > p_.move_limit * p_.box.h) return remesh(x, step);
  if (!motion_) motion_ = std::make_unique<HarmonicExtension>(*base_);
  std::vector<Point> d(base_->vertices.size(), Point(0, 0));
  for (std::size_t k = 0; k < x.size(); ++k) d[base_nodes_[k]] = x[k] - base_outline_[k];
  Mesh moved = motion_->moved(d);
  if (!(min_angle_deg(moved) >= 0.5 * base_angle_)) return remesh(x, step);
  step.outline_nodes = base_nodes_;
  return moved;
}

BodyFittedSolve BodyFittedFluid::solve(const Eigen::VectorXd& u) {
  BodyFittedSolve step;
  const std::vector<Point> x = deformed_outline(u);
  check_gap(x, step.gap);
  {
    const Stopwatch clock;
    step.mesh = std::make_unique<Mesh>(fluid_mesh(x, step));
    step.t_mesh = clock.elapsed();
  }
  {
    const Stopwatch clock;  // Stokes without penalty, v = 0 on Γ_u
    FluidBoundaryConditions bc = p_.boundary_conditions(*step.mesh);
    bc.dirichlet_labels.push_back(step.mesh->label("Gamma_u"));
    // ε is never used: χ = 0 everywhere (no fictitious domain).
    PenalisedStokes stokes(*step.mesh, p_.mu, 1.0, p_.f, bc, p_.rho > 0 ? kNavierStokesSolver : kDefaultSparseSolver);
    stokes.set_factorization(FluidFactorization::whole);
    if (p_.form != ViscousForm::symmetric) stokes.set_viscous_form(p_.form);
    if (p_.rho > 0) stokes.set_navier_stokes(p_.newton);
    stokes.set_chi(Eigen::VectorXd::Zero(step.mesh->num_triangles()));
    step.solution = stokes.solve();
    step.unknowns = stokes.unknowns();
    const FluidSolution& s = step.solution;
    if (!s.v1.allFinite() || !s.v2.allFinite() || !s.p.allFinite())
      throw SolverFailure("the body-fitted fluid solve gave a non-finite velocity or pressure");
    step.t_fluid = clock.elapsed();
  }
  {
    const Stopwatch clock;  // the residual at the outline's nodes → the structure's load
    const Eigen::Matrix2Xd R =
        momentum_residual(*step.mesh, MomentumModel{p_.mu, p_.form, p_.rho}, p_.f, step.solution, step.outline_nodes);
    Eigen::VectorXd pressure(static_cast<Eigen::Index>(x.size()));
    for (std::size_t k = 0; k < x.size(); ++k)
      pressure[static_cast<Eigen::Index>(k)] = step.solution.p[step.outline_nodes[k]];
    step.load = body_fitted_load(reference_, outline_, R, pressure, u, p_.normal);
    step.t_transfer = clock.elapsed();
  }
  return step;
}

}  // namespace fsi
