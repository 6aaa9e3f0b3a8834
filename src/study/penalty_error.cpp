#include "study/penalty_error.hpp"

namespace fsi {

PenaltyError penalty_error(double eps, double value, double value_check, double ratio) {
  PenaltyError e;
  e.eps = eps, e.eps_check = eps * ratio * ratio;
  e.value = value, e.value_check = value_check;
  if (std::isfinite(value) && std::isfinite(value_check) && ratio > 1)
    e.error_bar =
        kPenaltySafety * std::abs(value_check - value) / (ratio - 1);  // r^{2q} − 1, q = 1/2
  return e;
}

}  // namespace fsi
