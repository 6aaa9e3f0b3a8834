// output.probes (SPEC §11): reference points where summary.json and history.csv report
// the displacement; output.fluid_probes (SPEC §10): points of D where summary.json
// reports the flow. Whether each lies in Ω_S0 or D is known once the meshes are made
// (run/mesh_checks.cpp).
#include <string>

#include "io/case.hpp"
#include "io/case_section.hpp"

namespace fsi::case_detail {
namespace {

// Each probe is one point location per fixed-point pass and two history.csv columns.
constexpr std::size_t kMaxProbes = 1000;

std::string allowed(const std::string& key) {
  return key + " = [[x, y], ...], at most " + std::to_string(kMaxProbes) + " points, each coordinate " + kSigned.text();
}

// An entry's problem, named by its place counted from 1 as [[obstacles]]'s
// ("output.probes[3]"), from where the key came (the file or --set).
[[noreturn]] void bad_entry(const Origin& origin, const std::string& key, std::size_t i, const std::string& problem) {
  throw InputError(origin.of(key) + ": " + key + "[" + std::to_string(i + 1) + "] " + problem + "; allowed: " + allowed(key));
}

}  // namespace

std::vector<Point> read_probes(Section& output, const Origin& origin, const std::string& name) {
  const toml::array* a = output.array(name);
  if (!output.has(name)) return {};
  const std::string key = "output." + name;
  if (!a) fail(origin, key, "must be an array of [x, y] points", allowed(key));
  if (a->size() > kMaxProbes) fail(origin, key, "has " + std::to_string(a->size()) + " points", allowed(key));
  std::vector<Point> probes;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::array* xy = (*a)[i].as_array();
    if (!xy || xy->size() != 2 || !(*xy)[0].is_number() || !(*xy)[1].is_number())
      bad_entry(origin, key, i, "is not [x, y] (two numbers)");
    const Point p(as_double((*xy)[0]), as_double((*xy)[1]));
    if (!p.allFinite()) bad_entry(origin, key, i, "must be finite");
    if (!kSigned.contains(p.x()) || !kSigned.contains(p.y()))
      bad_entry(origin, key, i, "= [" + shortest(p.x()) + ", " + shortest(p.y()) + "] is out of range");
    probes.push_back(p);
  }
  return probes;
}

}  // namespace fsi::case_detail
