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

const std::vector<Quantity>& quantities(bool with_fluid) {
  static const std::vector<Quantity> structure = {
      {"max_displacement", "m", [](const Json& s) { return at(s, "max_displacement"); }},
      {"tip_displacement", "m",
       [](const Json& s) { return std::hypot(component(s, "tip_displacement", 0), component(s, "tip_displacement", 1)); }},
      {"contact_x_min", "m", [](const Json& s) { return in(s, "contact", "x_min"); }},
      {"contact_x_max", "m", [](const Json& s) { return in(s, "contact", "x_max"); }},
      {"contact_x_centroid", "m", [](const Json& s) { return in(s, "contact", "x_centroid"); }},
      {"contact_force", "N/m", [](const Json& s) { return in(s, "contact", "pressure_resultant"); }}};
  static const std::vector<Quantity> coupled = [] {
    std::vector<Quantity> q = structure;
    q.push_back({"fluid_velocity_l2_in_structure", "m^2/s", [](const Json& s) { return at(s, "fluid_velocity_l2_in_structure"); }});
    q.push_back({"structure_force_x", "N/m", [](const Json& s) { return component(s, "structure_force", 0); }});
    q.push_back({"structure_force_y", "N/m", [](const Json& s) { return component(s, "structure_force", 1); }});
    q.push_back({"structure_load_x", "N/m", [](const Json& s) { return component(s, "structure_load", 0); }});
    q.push_back({"structure_load_y", "N/m", [](const Json& s) { return component(s, "structure_load", 1); }});
    return q;
  }();
  return with_fluid ? coupled : structure;
}

}  // namespace fsi
