#include "run/point_text.hpp"

#include "common/format.hpp"

namespace fsi {

std::string point_text(const Point& p) {
  std::string text = "(";  // built step by step: "(" + std::string trips GCC 12's -Wrestrict
  text += shortest(p.x());
  text += ", ";
  text += shortest(p.y());
  return text + ")";
}

}  // namespace fsi
