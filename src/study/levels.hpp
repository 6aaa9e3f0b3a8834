// The levels of a refinement study: the case with every size key divided by r^i
// (structure.h, fluid.h, fluid.h_near), ε following coupling.eps_rule, each level's
// output in its own directory. All levels are built and validated before any runs.
// `refine` = "fluid" or "structure" refines one mesh only, the other kept as given:
// the two meshes' errors can have opposite signs (docs/validation.md), so refined
// together they may cancel into a sequence without an order; refined apart, each
// source's order and GCI can be measured.
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"

namespace fsi {

struct LevelSpec {
  int index = 0;        // 1 = the case as given (coarsest)
  std::string scheme;   // the coupling scheme of this run
  Case c;
};

// Levels 1…n for each scheme (the first scheme is the study's own; empty: the case's
// scheme only). Throws InputError naming the level for a level the case loader
// refuses (a size beyond the limits, say).
std::vector<LevelSpec> make_levels(const CaseSource& source, const std::vector<std::string>& overrides,
                                   int levels, double ratio, const std::vector<std::string>& schemes,
                                   const std::string& out_dir, const std::string& refine = "all");

}  // namespace fsi
