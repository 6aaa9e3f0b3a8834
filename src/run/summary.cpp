#include "run/summary.hpp"

#include "io/atomic_file.hpp"

namespace fsi {

Json to_json(const Case& c) {
  auto vec = [](const Point& p) { return Json::array({p.x(), p.y()}); };
  Json j;
  j["name"] = c.name;
  const auto& s = c.structure;
  j["structure"] = {{"L", s.L}, {"H", s.H},          {"E", s.E}, {"nu", s.nu},
                    {"f", vec(s.f)}, {"h_N", vec(s.h_N)}, {"h", s.h}, {"mesh", s.mesh}};
  const auto& o = c.obstacle;
  j["obstacle"] = {{"x0", o.x0}, {"y0", o.y0}, {"r", o.r}, {"gamma", o.gamma}};
  if (c.fluid) {
    const auto& f = *c.fluid;
    j["fluid"] = {{"L1", f.L1},     {"H1", f.H1}, {"H2", f.H2},     {"mu", f.mu},  {"f", vec(f.f)},
                  {"Vmax", f.Vmax}, {"h", f.h},   {"mesh", f.mesh}, {"chi", f.chi}};
    const auto& k = c.coupling;
    j["coupling"] = {{"eps", k.eps},
                     {"omega", k.omega},
                     {"tol", k.tol},
                     {"max_iterations", k.max_iterations},
                     {"scheme", k.scheme}};
  }
  j["contact"] = {{"solver", c.contact.solver}};
  j["output"] = {{"dir", c.output.dir}, {"png", c.output.png}, {"vtu", c.output.vtu}};
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
  return j;
}

Json timing_json(const PhaseTimes& times, double total) {
  Json j = {{"total", total}};
  for (const char* phase : {"mesh", "fluid", "structure", "transfer"}) j[phase] = times.get(phase);
  for (const auto& [phase, seconds] : times.all())
    if (!j.contains(phase)) j[phase] = seconds;
  return j;
}

void write_json(const std::string& path, const Json& j) {
  write_atomically(path, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

}  // namespace fsi
