#include "run/outputs/summary.hpp"

#include <cmath>

#include "io/atomic_file.hpp"
#include "fem/probes.hpp"

namespace fsi {

namespace {

Json vec(const Point& p) { return Json::array({p.x(), p.y()}); }

// A load of SPEC §10 as it was given: a number as a number, an expression as its text.
Json load_json(double value, const std::string& expression) { return expression.empty() ? Json(value) : Json(expression); }
Json load_json(const Point& p, const std::array<std::string, 2>& expressions) {
  return Json::array({load_json(p.x(), expressions[0]), load_json(p.y(), expressions[1])});
}

}  // namespace

Json to_json(const StructureParams& s) {
  return {{"shape", s.shape},  {"L", s.L},      {"H", s.H},          {"E", s.E},
          {"nu", s.nu},        {"f", load_json(s.f, s.f_expression)}, {"h_N", vec(s.h_N)}, {"h", s.h},
          {"mesh", s.mesh},    {"geo", s.geo},  {"model", s.model},  {"element", s.element},
          {"mesher", s.mesher}, {"rho", s.rho},    {"v0", vec(s.v0)},   {"clamped", s.clamped},
          {"mass", s.mass}};
}

Json to_json(const ObstacleParams& o) {
  return {{"x0", o.x0}, {"y0", o.y0}, {"r", o.r}, {"gamma", o.gamma}};
}

Json to_json(const FluidParams& f) {
  Json j = {{"L1", f.L1},
            {"H1", f.H1},
            {"H2", f.H2},
            {"mu", f.mu},
            {"f", load_json(f.f, f.f_expression)},
            {"Vmax", load_json(f.Vmax, f.Vmax_expression)},
            {"h", f.h},
            {"mesh", f.mesh},
            {"chi", f.chi},
            {"factorization", f.factorization},
            {"keep_far_factors_mb", f.keep_far_factors_mb},
            {"h_near", f.h_near}, {"h_obstacles", f.h_obstacles},
            {"band", f.band_box ? Json(*f.band_box) : Json(f.band)},
            {"method", f.method},
            {"mesher", f.mesher},
            {"model", f.model},
            {"viscous_form", f.viscous_form},
            {"element", f.element},
            {"newton_tol", f.newton_tol},
            {"newton_max_steps", f.newton_max_steps},
            {"linear_solver", f.linear_solver},
            {"linear_tol", f.linear_tol},
            {"linear_max_iterations", f.linear_max_iterations},
            {"krylov", f.krylov}};
  if (f.rho > 0) j["rho"] = f.rho;  // 0: not given (Stokes)
  for (std::size_t k = 0; k < kBoxSideKeys.size(); ++k) j[kBoxSideKeys[k]] = f.sides[k];
  return j;
}

Json to_json(const CouplingParams& k) {
  return {{"eps", k.eps}, {"omega", k.omega}, {"tol", k.tol}, {"max_iterations", k.max_iterations},
          {"scheme", k.scheme}, {"eps_rule", k.eps_rule}, {"force", k.force},
          {"force_sampling", k.force_sampling}, {"reuse", k.reuse}};
}

Json to_json(const ContactParams& c) { return {{"solver", c.solver}, {"gap", c.gap}, {"boundary", c.boundary}}; }

Json to_json(const OutputParams& o) {
  Json j = {{"dir", o.dir}, {"png", o.png}, {"vtu", o.vtu}, {"vtu_format", o.vtu_format}};
  if (!o.probes.empty()) {  // absent without probes: the parameters of earlier runs unchanged
    j["probes"] = Json::array();
    for (const Point& p : o.probes) j["probes"].push_back(point_json(p));
  }
  if (!o.fluid_probes.empty()) {
    j["fluid_probes"] = Json::array();
    for (const Point& p : o.fluid_probes) j["fluid_probes"].push_back(point_json(p));
  }
  return j;
}

Json to_json(const Case& c) {
  Json j;
  j["name"] = c.name;
  j["structure"] = to_json(c.structure);
  j["obstacle"] = to_json(c.obstacle);
  if (c.obstacles_given) {
    Json list = Json::array();
    for (const ObstacleSpec& o : c.obstacles) {
      Json e = {{"shape", o.shape}};
      if (o.shape == "disk") e["x0"] = o.x0, e["y0"] = o.y0, e["r"] = o.r;
      if (o.shape == "half-plane") e["point"] = {o.point.x(), o.point.y()}, e["normal"] = {o.normal.x(), o.normal.y()};
      if (o.shape == "polygon") {
        e["points"] = Json::array();
        for (const Point& p : o.points) e["points"].push_back({p.x(), p.y()});
      }
      list.push_back(e);
    }
    j["obstacles"] = list;
  }
  if (c.fluid) j["fluid"] = to_json(*c.fluid);
  j["coupling"] = to_json(c.coupling);
  j["contact"] = to_json(c.contact);
  j["output"] = to_json(c.output);
  if (c.time)
    j["time"] = {{"dt", c.time->dt}, {"t_end", c.time->t_end}, {"scheme", c.time->scheme},
                 {"output_every", c.time->output_every}, {"checkpoint_every", c.time->checkpoint_every},
                 {"start_from", c.time->start_from}, {"convection", c.time->convection}};
  return j;
}

Json to_json(const MeshStatistics& s) {
  return {{"triangles", s.triangles},
          {"vertices", s.vertices},
          {"min_angle_deg", s.min_angle_deg},
          {"h_min", s.h_min},
          {"h_max", s.h_max}};
}

Json to_json(const KktResiduals& k) {
  return {{"stationarity", k.stationarity},
          {"feasibility", k.feasibility},
          {"complementarity", k.complementarity},
          {"dual_feasibility", k.dual_feasibility}};
}

Json to_json(const ContactSummary& s) {
  Json j = {{"active_nodes", s.active_nodes}};
  j["x_min"] = s.active_nodes ? Json(s.x_min) : Json(nullptr);
  j["x_max"] = s.active_nodes ? Json(s.x_max) : Json(nullptr);
  j["max_multiplier"] = s.max_multiplier;
  j["pressure_resultant"] = s.pressure_resultant;
  j["x_centroid"] = s.pressure_resultant > 0 ? Json(s.x_centroid) : Json(nullptr);
  return j;
}

Json timing_json(const PhaseTimes& times, double total) {
  Json j = {{"total", total}};
  for (const char* phase : {"mesh", "fluid", "structure", "transfer"}) j[phase] = times.get(phase);
  for (const auto& [phase, seconds] : times.all())
    if (!j.contains(phase)) j[phase] = seconds;
  return j;
}

Json point_json(const Point& p) { return Json::array({p.x(), p.y()}); }

std::optional<Point> tip_of(const Case& c) {
  if (!c.structure.rectangle() && !c.structure.extent_given) return std::nullopt;
  return Point(c.structure.L, c.structure.H / 2);
}

Json tip_displacement_json(const Case& c, const Mesh& reference, const Eigen::VectorXd& u, const P2Space* p2) {
  const std::optional<Point> tip = tip_of(c);
  return tip ? point_json(displacement_at(reference, u, *tip, p2)) : Json(nullptr);
}

void add_displacement_at(Json& j, const Case& c, const Mesh& reference, const Eigen::VectorXd& u, const P2Space* p2) {
  if (c.output.probes.empty()) return;
  const std::vector<Point> d = ProbeSet(reference, c.output.probes, p2).displacements(u);
  Json list = Json::array();
  for (std::size_t i = 0; i < d.size(); ++i) list.push_back({{"point", point_json(c.output.probes[i])}, {"u", point_json(d[i])}});
  j["displacement_at"] = list;
}

double max_displacement(const Eigen::VectorXd& u) {
  const Eigen::Index nv = u.size() / 2;
  double m = 0;
  for (Eigen::Index i = 0; i < nv; ++i) m = std::max(m, std::hypot(u[i], u[nv + i]));
  return m;
}

std::string json_text(const Json& j, int indent) {
  // Paths may hold any bytes (Linux file names are not UTF-8 by law): invalid
  // sequences are shown as U+FFFD instead of throwing (found by fuzzing --out).
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

void write_json(const std::string& path, const Json& j) {
  write_atomically(path, [&](std::ostream& out) { out << json_text(j, 2) << '\n'; });
}

}  // namespace fsi
