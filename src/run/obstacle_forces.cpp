#include "run/obstacle_forces.hpp"

#include "common/errors.hpp"
#include "fluid/stokes_residual.hpp"

namespace fsi {

Point hole_force(const Mesh& mesh, double mu, const Point& f_F, const FluidSolution& s, int label,
                 const Eigen::VectorXd& kappa) {
  const Eigen::Matrix2Xd R =
      momentum_residual(mesh, mu, [f_F](const Point&) { return f_F; }, s, mesh.vertices_on(label), kappa);
  return -R.rowwise().sum();
}

Json obstacle_forces_json(const Case& c, FluidSetup& f) {
  Json list = Json::array();
  const FluidSolution* s = nullptr;
  if (f.stokes->has_solution()) {
    try {
      s = &f.stokes->solution();  // the far field too: a hole may lie outside the near region
    } catch (const SolverFailure&) {
      s = nullptr;
    }
  }
  const Eigen::VectorXd kappa = f.stokes->last_solution_chi() / f.stokes->eps();
  // [[obstacles]]' holes Sigma_5_i, or [obstacle]'s one disk Sigma_5.
  const std::size_t count = c.obstacles_given ? c.obstacles.size() : 1;
  for (std::size_t i = 0; i < count; ++i) {
    const int label = f.mesh->label(c.obstacles_given ? "Sigma_5_" + std::to_string(i + 1) : std::string("Sigma_5"));
    list.push_back({{"force", s ? point_json(hole_force(*f.mesh, c.fluid->mu, c.fluid->f, *s, label, kappa))
                                : Json(nullptr)}});
  }
  return list;
}

}  // namespace fsi
