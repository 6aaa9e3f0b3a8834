#include "common/format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace fsi {

std::string shortest(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, v);  // shortest round trip
  return ec == std::errc{} ? std::string(text, end) : std::to_string(v);
}

std::string approx(double v, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace fsi
