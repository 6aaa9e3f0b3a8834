#include "study/richardson.hpp"

#include <algorithm>
#include <cmath>

namespace fsi {
namespace {

// p of the triple (coarse, middle, fine), signed: ≤ 0 when the differences grow.
double order_of(double coarse, double middle, double fine, double ratio) {
  const double e21 = middle - fine, e32 = coarse - middle;
  return std::log(std::abs(e32 / e21)) / std::log(ratio);
}

ConvergenceKind kind_of(double coarse, double middle, double fine) {
  const double e21 = middle - fine, e32 = coarse - middle;
  // The two finest agree exactly (a contact zone's ends, which sit on vertices, do
  // that): nothing left to extrapolate.
  if (e21 == 0) return ConvergenceKind::exact;
  if (e32 == 0) return ConvergenceKind::divergent;  // nothing changed, then something did
  const double R = e21 / e32;
  if (R < 0) return ConvergenceKind::oscillatory;
  return R < 1 ? ConvergenceKind::monotone : ConvergenceKind::divergent;
}

}  // namespace

ConvergenceEstimate estimate_convergence(const std::vector<double>& values, double ratio, double safety) {
  ConvergenceEstimate e;
  const std::size_t n = values.size();
  if (n < 3 || !(ratio > 1)) return e;
  for (std::size_t i = 0; i + 2 < n; ++i) {
    const bool exact = kind_of(values[i], values[i + 1], values[i + 2]) == ConvergenceKind::exact;
    e.orders.push_back(exact ? NAN : order_of(values[i], values[i + 1], values[i + 2], ratio));
  }
  const double phi1 = values[n - 1], phi2 = values[n - 2], phi3 = values[n - 3];
  e.kind = kind_of(phi3, phi2, phi1);
  e.observed_order = e.orders.back();
  if (e.kind == ConvergenceKind::exact) {
    e.extrapolated = phi1;
    e.gci = e.gci_abs = 0;
  } else if (e.kind == ConvergenceKind::monotone) {
    const double rp = std::pow(ratio, e.observed_order);
    e.extrapolated = phi1 + (phi1 - phi2) / (rp - 1);
    e.gci_abs = safety * std::abs(phi2 - phi1) / (rp - 1);
    e.gci = phi1 != 0 ? e.gci_abs / std::abs(phi1) : NAN;
  }
  if (e.kind == ConvergenceKind::monotone || e.kind == ConvergenceKind::exact) e.error_bar = e.gci_abs;
  if (e.kind == ConvergenceKind::oscillatory)
    e.error_bar = 3 * (std::max({phi1, phi2, phi3}) - std::min({phi1, phi2, phi3})) / 2;
  if (n >= 4) {
    const ConvergenceKind previous = kind_of(values[n - 4], phi3, phi2);
    const double p_previous = e.orders[e.orders.size() - 2];
    e.asymptotic = (e.kind == ConvergenceKind::exact) ||
                   (e.kind == ConvergenceKind::monotone && previous == ConvergenceKind::monotone &&
                    std::abs(e.observed_order - p_previous) <= 0.3);
  }
  return e;
}

std::string to_string(ConvergenceKind kind) {
  switch (kind) {
    case ConvergenceKind::monotone: return "monotone";
    case ConvergenceKind::oscillatory: return "oscillatory";
    case ConvergenceKind::divergent: return "divergent";
    case ConvergenceKind::exact: return "exact";
    case ConvergenceKind::too_few: return "too few levels";
  }
  return "";
}

}  // namespace fsi
