#include "run/outputs/obstacle_forces.hpp"

#include "common/errors.hpp"
#include "fluid/stokes_residual.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_setup.hpp"

namespace fsi {

Json obstacle_forces_json(const Case& c, FluidSetup& f) {
  const FluidSolution* s = nullptr;
  if (f.stokes->has_solution()) {
    try {
      s = &f.stokes->solution();  // the far field too: a hole may lie outside the near region
    } catch (const SolverFailure&) {
      s = nullptr;
    }
  }
  return hole_forces_json(c, *f.mesh, s, f.stokes->last_solution_chi() / f.stokes->eps());
}

Json hole_forces_json(const Case& c, const Mesh& mesh, const FluidSolution* s, const Eigen::VectorXd& kappa) {
  Json list = Json::array();
  // [[obstacles]]' holes Sigma_5_i, or [obstacle]'s one disk Sigma_5.
  const std::size_t count = c.obstacles_given ? c.obstacles.size() : 1;
  for (std::size_t i = 0; i < count; ++i) {
    if (!s) {
      list.push_back({{"force", nullptr}});
      continue;
    }
    const int label = mesh.label(c.obstacles_given ? "Sigma_5_" + std::to_string(i + 1) : std::string("Sigma_5"));
    const Point force = hole_force(mesh, momentum_model(*c.fluid), fluid_body_force(*c.fluid), *s, label, kappa);
    list.push_back({{"force", point_json(force)}});
  }
  return list;
}

}  // namespace fsi
