#include "study/quantities.hpp"

#include <cmath>

namespace fsi {
namespace {

double number(const Json& j) { return j.is_number() ? j.get<double>() : NAN; }

double at(const Json& s, const char* key) { return s.contains(key) ? number(s[key]) : NAN; }

double in(const Json& s, const char* outer, const char* key) {
  return s.contains(outer) && s[outer].is_object() && s[outer].contains(key) ? number(s[outer][key]) : NAN;
}

double component(const Json& s, const char* key, int i) {
  return s.contains(key) && s[key].is_array() && s[key].size() == 2 ? number(s[key][i]) : NAN;
}

}  // namespace

namespace {

std::vector<Quantity> structure_quantities() {
  return {{"max_displacement", "m", [](const Json& s) { return at(s, "max_displacement"); }},
          {"tip_displacement", "m",
           [](const Json& s) { return std::hypot(component(s, "tip_displacement", 0), component(s, "tip_displacement", 1)); }},
          {"contact_x_min", "m", [](const Json& s) { return in(s, "contact", "x_min"); }},
          {"contact_x_max", "m", [](const Json& s) { return in(s, "contact", "x_max"); }},
          {"contact_x_centroid", "m", [](const Json& s) { return in(s, "contact", "x_centroid"); }},
          {"contact_force", "N/m", [](const Json& s) { return in(s, "contact", "pressure_resultant"); }}};
}

// displacement_at[k].u[i] (output.probes' k-th point).
double probe(const Json& s, std::size_t k, int i) {
  if (!s.contains("displacement_at") || !s["displacement_at"].is_array() || s["displacement_at"].size() <= k) return NAN;
  return component(s["displacement_at"][k], "u", i);
}

// obstacles[k].force[i].
double obstacle_force(const Json& s, std::size_t k, int i) {
  if (!s.contains("obstacles") || !s["obstacles"].is_array() || s["obstacles"].size() <= k) return NAN;
  return component(s["obstacles"][k], "force", i);
}

// fluid_at[k]'s pressure (i < 0) or velocity component i.
double fluid_probe(const Json& s, std::size_t k, int i) {
  if (!s.contains("fluid_at") || !s["fluid_at"].is_array() || s["fluid_at"].size() <= k) return NAN;
  const Json& e = s["fluid_at"][k];
  return i < 0 ? at(e, "p") : component(e, "v", i);
}

double total_force(const Json& s, std::size_t obstacles, int i) {
  double sum = component(s, "structure_force", i);
  for (std::size_t k = 0; k < obstacles; ++k) sum += obstacle_force(s, k, i);
  return sum;
}

}  // namespace

std::vector<Quantity> quantities(const Case& c) {
  const bool structure = c.structure.shape != "none", fluid = c.fluid.has_value();
  std::vector<Quantity> q;
  if (structure) q = structure_quantities();
  if (structure)
    for (std::size_t k = 0; k < c.output.probes.size(); ++k)
      for (int i = 0; i < 2; ++i)
        q.push_back({"probe_" + std::to_string(k + 1) + "_u_" + "xy"[i], "m", [k, i](const Json& s) { return probe(s, k, i); }});
  if (structure && fluid) {
    q.push_back({"fluid_velocity_l2_in_structure", "m^2/s", [](const Json& s) { return at(s, "fluid_velocity_l2_in_structure"); }});
    q.push_back({"structure_force_x", "N/m", [](const Json& s) { return component(s, "structure_force", 0); }});
    q.push_back({"structure_force_y", "N/m", [](const Json& s) { return component(s, "structure_force", 1); }});
    q.push_back({"structure_load_x", "N/m", [](const Json& s) { return component(s, "structure_load", 0); }});
    q.push_back({"structure_load_y", "N/m", [](const Json& s) { return component(s, "structure_load", 1); }});
  }
  if (!fluid) return q;
  for (std::size_t k = 0; k < c.output.fluid_probes.size(); ++k) {
    const std::string name = "fluid_probe_" + std::to_string(k + 1);
    q.push_back({name + "_p", "Pa", [k](const Json& s) { return fluid_probe(s, k, -1); }});
    q.push_back({name + "_v_x", "m/s", [k](const Json& s) { return fluid_probe(s, k, 0); }});
    q.push_back({name + "_v_y", "m/s", [k](const Json& s) { return fluid_probe(s, k, 1); }});
  }
  if (c.output.fluid_probes.size() >= 2)  // e.g. the DFG benchmark's Δp
    q.push_back({"fluid_probe_pressure_difference", "Pa",
                 [](const Json& s) { return fluid_probe(s, 0, -1) - fluid_probe(s, 1, -1); }});
  const std::size_t obstacles = c.obstacles_given ? c.obstacles.size() : 1;
  for (std::size_t k = 0; k < obstacles; ++k)
    for (int i = 0; i < 2; ++i)
      q.push_back({"obstacle_" + std::to_string(k + 1) + "_force_" + "xy"[i], "N/m",
                   [k, i](const Json& s) { return obstacle_force(s, k, i); }});
  if (structure)
    for (int i = 0; i < 2; ++i)
      q.push_back({std::string("fluid_force_") + "xy"[i], "N/m", [obstacles, i](const Json& s) { return total_force(s, obstacles, i); }});
  return q;
}

}  // namespace fsi
