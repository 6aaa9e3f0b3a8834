#include "run/taylor_hood_setup.hpp"

#include <stdexcept>

#include "common/errors.hpp"
#include "fem/point_locator.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_setup.hpp"
#include "run/outputs/obstacle_forces.hpp"

namespace fsi {

std::vector<CircleBoundary> disk_holes(const Case& c, const Mesh& mesh) {
  std::vector<CircleBoundary> circles;
  if (!c.fluid->mesh.empty()) return circles;
  if (!c.obstacles_given) {
    if (mesh.has_label("Sigma_5")) circles.push_back({mesh.label("Sigma_5"), {c.obstacle.x0, c.obstacle.y0}, c.obstacle.r});
    return circles;
  }
  for (std::size_t i = 0; i < c.obstacles.size(); ++i) {
    const ObstacleSpec& o = c.obstacles[i];
    const std::string label = "Sigma_5_" + std::to_string(i + 1);
    if (o.shape == "disk" && mesh.has_label(label)) circles.push_back({mesh.label(label), {o.x0, o.y0}, o.r});
  }
  return circles;
}

TaylorHoodSetup make_taylor_hood(const Case& c, Mesh mesh, double t) {
  const FluidParams& f = *c.fluid;
  TaylorHoodSetup s;
  s.mesh = std::make_unique<Mesh>(std::move(mesh));
  s.space = std::make_unique<P2Space>(*s.mesh);
  try {
    // Degree 5: exact for the convection term's P2·P1·P2 on straight triangles.
    s.geometry = std::make_unique<IsoP2Geometry>(*s.space, disk_holes(c, *s.mesh), 5);
  } catch (const std::invalid_argument& e) {
    throw SolverFailure(std::string(e.what()) + "; a smaller fluid.h_obstacles or fluid.h_near at the disks helps");
  }
  const TaylorHoodModel model{f.mu, f.viscous_form == "gradient" ? ViscousForm::gradient : ViscousForm::symmetric,
                              f.navier_stokes() ? f.rho : 0.0};
  s.system = std::make_unique<TaylorHoodSystem>(*s.geometry, model, fluid_body_force(f, t),
                                                box_boundary_conditions(*s.mesh, f, t));
  TaylorHoodOptions options;
  options.tol = f.newton_tol;
  options.max_steps = f.newton_max_steps;
  if (f.linear_solver != "mumps") options.solver = f.linear_solver;
  options.linear = LinearSolverOptions(f.linear_tol, f.linear_max_iterations, f.krylov);
  s.flow = std::make_unique<TaylorHoodFlow>(*s.system, options);
  return s;
}

void set_taylor_hood_data(TaylorHoodSetup& s, const Case& c, double t) {
  s.system->set_data(fluid_body_force(*c.fluid, t), box_boundary_conditions(*s.mesh, *c.fluid, t));
}

std::vector<Point> taylor_hood_hole_forces(TaylorHoodSetup& s, const Case& c) {
  std::vector<int> labels;
  for (const std::string& hole : obstacle_hole_names(c)) labels.push_back(s.mesh->label(hole));
  return s.flow->forces(labels);
}

Json taylor_hood_probes_json(const Case& c, const TaylorHoodSetup& s) {
  Json list = Json::array();
  if (c.output.fluid_probes.empty()) return list;
  const PointLocator locator(*s.mesh);
  for (const Point& x : c.output.fluid_probes) {
    const Location where = locator.locate_or_nearest(x);
    const FluidValue value = s.flow->at(where.triangle, where.lambda);
    list.push_back({{"point", point_json(x)}, {"v", point_json(value.v)}, {"p", value.p}});
  }
  return list;
}

Json taylor_hood_json(const TaylorHoodSetup& s) {
  const TaylorHoodFlow& flow = *s.flow;
  const TaylorHoodTiming& t = flow.timing();
  Json j = {{"method", "penalised"},
            {"element", "taylor-hood"},
            {"unknowns", s.system->unknowns()},
            {"nonzeros", static_cast<long>(s.system->jacobian().nonZeros())},
            {"velocity_nodes", s.system->velocity_nodes()},
            {"curved_triangles", s.geometry->curved_triangles()},
            {"solver", flow.solver_name()},
            {"analyses", flow.analyses()},
            {"factorizations", flow.factorizations()},
            {"chord_steps", flow.chord_steps()},
            {"assembly_s", t.assembly},
            {"factorization_s", t.factorization},
            {"solve_s", t.solve},
            {"factorization", "whole"}};
  add_linear_solver_json(j, flow.solver_name(), t.linear_iterations, flow.options().linear.krylov);
  if (s.system->model().rho > 0) j["newton"] = newton_json(flow.report());
  return j;
}

}  // namespace fsi
