// Internal to the case loader (case.cpp, case_checks.cpp): allowed ranges, where a
// key came from, and the one way a problem is reported.
#pragma once

#include <limits>
#include <set>
#include <string>
#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace fsi {
struct Case;
}

namespace fsi::case_detail {

constexpr double inf = std::numeric_limits<double>::infinity();

// Dimensional inputs (SI) are 0 where zero means something (loads, positions) or of
// a magnitude in [1e-30, 1e30]: every product of up to ten such factors, the most
// any formula here forms (ε⁻¹ · area · velocity · ...), stays a normal double
// (1e±308), so nothing under- or overflows on the way. Physical values lie far
// inside: E of gels (1e2 Pa) to diamond (1e12), lengths of cells to coasts.
constexpr double kMinMagnitude = 1e-30, kMaxMagnitude = 1e30;

// An interval with open or closed ends, or (signed) "0 or a magnitude in [lo, hi]".
struct Range {
  double lo = -inf, hi = inf;
  bool lo_closed = false, hi_closed = false;
  bool zero_or_magnitude = false;
  bool contains(double v) const;
  std::string text() const;
};

inline const Range kAny{};
inline const Range kSize{kMinMagnitude, kMaxMagnitude, true, true};         // lengths, moduli, ...
inline const Range kSigned{kMinMagnitude, kMaxMagnitude, true, true, true};  // loads, positions
inline const Range kNonNegative{0, inf, true, false};
inline Range open(double a, double b) { return {a, b, false, false}; }
inline Range left_open(double a, double b) { return {a, b, false, true}; }

// Where each key came from: the case file, or a --set override.
struct Origin {
  std::string file;
  std::set<std::string> overridden;
  std::string of(const std::string& key) const { return overridden.count(key) ? "--set " + key : file; }
  // "structure.L = 0.3" and, if it came from elsewhere than `other`'s origin, where.
  std::string value(const std::string& key, double v, const std::string& other) const {
    const std::string text = key + " = " + shortest(v);
    return of(key) == of(other) ? text : text + ", from " + of(key);
  }
};

// Throws InputError "<origin of key>: <key> <problem>; allowed: <allowed>".
[[noreturn]] void fail(const Origin& origin, const std::string& key, const std::string& problem,
                       const std::string& allowed);

// [[obstacles]] into c.obstacles (case_obstacles.cpp).
void read_obstacles(const toml::table& root, const Origin& origin, fsi::Case& c);

}  // namespace fsi::case_detail
