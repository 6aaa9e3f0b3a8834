#include "run/outputs/obstacle_forces.hpp"

#include "common/errors.hpp"
#include "fem/point_locator.hpp"
#include "fluid/fluid_field.hpp"
#include "fluid/stokes_residual.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_setup.hpp"

namespace fsi {

namespace {

// The last fluid solution made exact everywhere (a hole or a probe may lie outside the
// substructured solve's near region), or null.
const FluidSolution* whole_solution(FluidSetup& f) {
  if (!f.stokes->has_solution()) return nullptr;
  try {
    return &f.stokes->solution();
  } catch (const SolverFailure&) {
    return nullptr;
  }
}

}  // namespace

Json obstacle_forces_json(const Case& c, FluidSetup& f) {
  return hole_forces_json(c, *f.mesh, whole_solution(f), f.stokes->last_solution_chi() / f.stokes->eps());
}

Json fluid_probes_json(const Case& c, FluidSetup& f) { return fluid_probes_json(c, *f.mesh, whole_solution(f)); }

Json fluid_probes_json(const Case& c, const Mesh& mesh, const FluidSolution* s) {
  Json list = Json::array();
  if (c.output.fluid_probes.empty()) return list;
  const PointLocator locator(mesh);
  for (const Point& x : c.output.fluid_probes) {
    Json e = {{"point", point_json(x)}, {"v", nullptr}, {"p", nullptr}};
    if (s) {
      const FluidValue value = FluidField(locator, *s).at(locator.locate_or_nearest(x));
      e["v"] = point_json(value.v);
      e["p"] = value.p;
    }
    list.push_back(e);
  }
  return list;
}

std::vector<std::string> obstacle_hole_names(const Case& c) {
  if (!c.obstacles_given) return {"Sigma_5"};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) names.push_back("Sigma_5_" + std::to_string(i + 1));
  return names;
}

Json hole_forces_json(const Case& c, const Mesh& mesh, const FluidSolution* s, const Eigen::VectorXd& kappa) {
  if (!s) return hole_forces_json(c, nullptr);
  std::vector<Point> forces;
  for (const std::string& hole : obstacle_hole_names(c))
    forces.push_back(hole_force(mesh, momentum_model(*c.fluid), fluid_body_force(*c.fluid), *s, mesh.label(hole), kappa));
  return hole_forces_json(c, &forces);
}

Json hole_forces_json(const Case& c, const std::vector<Point>* forces) {
  Json list = Json::array();
  for (std::size_t i = 0; i < obstacle_hole_names(c).size(); ++i)
    list.push_back({{"force", forces ? point_json((*forces)[i]) : Json(nullptr)}});
  return list;
}

}  // namespace fsi
