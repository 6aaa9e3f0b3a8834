#include "run/fluid_setup.hpp"

#include "common/errors.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/fluid_band.hpp"
#include "run/mesh_checks.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

Mesh build_fluid_mesh(const Case& c, const std::optional<std::array<double, 4>>& band) {
  const FluidParams& f = *c.fluid;
  const ObstacleParams& o = c.obstacle;
  if (f.mesh.empty()) {
    try {
      FluidGeometry g{f.L1, f.H1, f.H2, o.x0, o.y0, o.r, f.h};
      if (band) g.h_near = f.h_near, g.band = *band;
      return generate_fluid_mesh(g);
    } catch (const MeshError& e) {  // the geometry was validated: Gmsh's failure, or ours
      throw SolverFailure(std::string("meshing the fluid box failed: ") + e.what());
    }
  }
  return read_case_mesh(c, "fluid.mesh", f.mesh, {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4", "Sigma_5"}, "D",
                        case_limits().fluid_triangles);
}

Mesh make_fluid_mesh(const Case& c) {
  std::optional<std::array<double, 4>> band;
  if (band_needs_structure(c)) {
    const StructureSetup s = make_structure(c, make_structure_mesh(c), nullptr);
    band = fluid_band_box(c, &s);
  } else {
    band = fluid_band_box(c, nullptr);
  }
  Mesh mesh = build_fluid_mesh(c, band);
  if (!c.fluid->mesh.empty()) check_fluid_mesh(c, mesh);
  return mesh;
}

FluidBoundaryConditions paper_boundary_conditions(const Mesh& mesh, const FluidParams& f) {
  FluidBoundaryConditions bc;
  for (const char* name : {"Sigma_1", "Sigma_3", "Sigma_4", "Sigma_5"})
    bc.dirichlet_labels.push_back(mesh.label(name));
  // The inflow on the label Σ4, whatever its coordinates (a mesh whose Σ4 is not at
  // y = H1 is refused by check_fluid_mesh). g vanishes at x = 0 and x = L1, so the
  // corners shared with the walls Σ1, Σ3 agree.
  const double L1 = f.L1, Vmax = f.Vmax;
  bc.dirichlet_values.emplace_back(mesh.label("Sigma_4"), [L1, Vmax](const Point& x) {
    return Point(0, Vmax * 4 * x.x() * (x.x() - L1) / (L1 * L1));
  });
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
