#include "study/levels.hpp"

#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace fsi {
namespace {

// The overrides of level i (0-based): sizes / r^i, ε · r^(−i p).
std::vector<std::string> level_overrides(const Case& base, int i, double ratio, const std::string& refine) {
  const double scale = std::pow(ratio, -i);
  std::vector<std::string> sets;
  if (refine != "fluid" && base.structure.shape != "none") sets.push_back("structure.h=" + shortest(base.structure.h * scale));
  if (base.fluid && refine != "structure") {
    sets.push_back("fluid.h=" + shortest(base.fluid->h * scale));
    if (base.fluid->h_near > 0) sets.push_back("fluid.h_near=" + shortest(base.fluid->h_near * scale));
    if (base.fluid->h_obstacles > 0) sets.push_back("fluid.h_obstacles=" + shortest(base.fluid->h_obstacles * scale));
    const double p = base.coupling.eps_power();
    if (p > 0) sets.push_back("coupling.eps=" + shortest(base.coupling.eps * std::pow(scale, p)));
  }
  return sets;
}

}  // namespace

std::vector<LevelSpec> make_levels(const CaseSource& source, const std::vector<std::string>& overrides,
                                   int levels, double ratio, const std::vector<std::string>& schemes,
                                   const std::string& out_dir, const std::string& refine) {
  const Case base = source.load(overrides);
  std::vector<std::string> runs = schemes;
  if (runs.empty()) runs.push_back(base.coupling.scheme);
  std::vector<LevelSpec> specs;
  // Contact only, or the fluid alone: no coupling to compare.
  const std::size_t schemes_run = base.fluid && base.structure.shape != "none" ? runs.size() : 1;
  for (std::size_t s = 0; s < schemes_run; ++s)
    for (int i = 0; i < levels; ++i) {
      std::vector<std::string> sets = overrides;
      const std::vector<std::string> sizes = level_overrides(base, i, ratio, refine);
      sets.insert(sets.end(), sizes.begin(), sizes.end());
      if (base.fluid && base.structure.shape != "none") sets.push_back("coupling.scheme=" + runs[s]);
      const std::string dir = "level-" + std::to_string(i + 1) + (s == 0 ? "" : "-" + runs[s]);
      LevelSpec spec{i + 1, runs[s], {}};
      try {
        spec.c = source.load(sets, (std::filesystem::path(out_dir) / dir).string());
      } catch (const InputError& e) {
        throw InputError("level " + std::to_string(i + 1) + " (sizes / " + shortest(std::pow(ratio, i)) +
                         "): " + e.what());
      }
      specs.push_back(std::move(spec));
    }
  return specs;
}

}  // namespace fsi
