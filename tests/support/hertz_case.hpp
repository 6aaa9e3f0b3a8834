// Hertz's problem as a case (SPEC §9): the half cylinder of
// tests/data/geo/hertz-half-cylinder.geo (R = 1, clamped on its flat top) pressed by its
// weight onto the floor y <= 0, contact by signed distance; `h` is structure.h (the
// contact zone is meshed at h/50).
#pragma once

#include <string>

namespace fsi::testing {

inline std::string hertz_case(const std::string& h) {
  return R"(name = "hertz"
[structure]
geo = ")" + std::string(FSICONTACT_SOURCE_DIR) + R"(/tests/data/geo/hertz-half-cylinder.geo"
E = 1.0
nu = 0.3
f = [0.0, -0.001]
h = )" + h + R"(
[[obstacles]]
shape = "half-plane"
point = [0.0, 0.0]
normal = [0.0, 1.0]
[contact]
gap = "normal"
)";
}

}  // namespace fsi::testing
