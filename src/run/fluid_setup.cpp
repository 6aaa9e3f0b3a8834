#include "run/fluid_setup.hpp"

#include "common/errors.hpp"
#include "mesh/gmsh_io.hpp"

namespace fsi {

Mesh make_fluid_mesh(const Case& c) {
  const FluidParams& f = *c.fluid;
  const ObstacleParams& o = c.obstacle;
  if (f.mesh.empty()) {
    try {
      return generate_fluid_mesh({f.L1, f.H1, f.H2, o.x0, o.y0, o.r, f.h});
    } catch (const MeshError& e) {
      throw SolverFailure(std::string("fluid mesh generation failed: ") + e.what());
    }
  }
  Mesh mesh;
  try {
    mesh = read_gmsh_file(f.mesh, {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4", "Sigma_5"}, "D");
  } catch (const MeshError& e) {
    throw InputError(c.source + ": fluid.mesh: " + e.what());
  }
  if (mesh.num_triangles() > kMaxFluidTriangles)
    throw InputError(c.source + ": fluid.mesh: " + f.mesh + " has " +
                     std::to_string(mesh.num_triangles()) + " triangles; allowed: at most " +
                     std::to_string(static_cast<long>(kMaxFluidTriangles)));
  return mesh;
}

FluidBoundaryConditions paper_boundary_conditions(const Mesh& mesh, const FluidParams& f) {
  FluidBoundaryConditions bc;
  for (const char* name : {"Sigma_1", "Sigma_3", "Sigma_4", "Sigma_5"})
    bc.dirichlet_labels.push_back(mesh.label(name));
  const double L1 = f.L1, H1 = f.H1, Vmax = f.Vmax;
  // Only Σ4 (y = H1) carries the inflow; g vanishes at its ends, so the corners
  // shared with Σ1, Σ3 agree.
  bc.g = [L1, H1, Vmax](const Point& x) {
    if (std::abs(x.y() - H1) > 1e-12 * std::max(1.0, std::abs(H1))) return Point(0, 0);
    return Point(0, Vmax * 4 * x.x() * (x.x() - L1) / (L1 * L1));
  };
  return bc;
}

FluidSetup make_fluid(const Case& c, Mesh mesh, double eps) {
  const FluidParams& f = *c.fluid;
  FluidSetup s;
  s.mesh = std::make_unique<Mesh>(std::move(mesh));
  s.locator = std::make_unique<PointLocator>(*s.mesh);
  s.chi = std::make_unique<ChiComputer>(*s.mesh, *s.locator, f.chi);
  const Point f_F = f.f;
  s.stokes = std::make_unique<PenalisedStokes>(*s.mesh, f.mu, eps, [f_F](const Point&) { return f_F; },
                                               paper_boundary_conditions(*s.mesh, f));
  s.stokes->set_factorization(f.factorization == "whole" ? FluidFactorization::whole : FluidFactorization::schur);
  s.stokes->set_far_factor_budget(f.keep_far_factors_mb);
  return s;
}

}  // namespace fsi
