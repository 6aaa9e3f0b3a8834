#include "coupling/fixed_point.hpp"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "coupling/fixed_point_loop.hpp"
#include "coupling/coupled_map.hpp"

namespace fsi {

FixedPointCoupling::FixedPointCoupling(FluidStep& fluid, StructureStep& structure, const Eigen::VectorXd& b_applied,
                                       Relaxation& relaxation, const SparseMatrix& M, double tol, int max_iterations)
    : H_(fluid, structure, b_applied), relaxation_(relaxation), tol_(tol), max_iterations_(max_iterations), M_(M) {}

std::string convergence_warning(const CouplingResult& r, double tol) {
  const std::size_t n = r.history.size();
  if (r.converged && r.final_norm > 0 && r.final_increment > 0.1 * r.final_norm) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "the stop says little: the last increment %.2e is %.0f%% of the displacement's own L2 norm "
                  "%.2e, so tol %g is coarse for this problem's scale; a smaller coupling.tol",
                  r.final_increment, 100 * r.final_increment / r.final_norm, r.final_norm, tol);
    return text;
  }
  if (!r.converged || n < 11) return "";
  std::vector<double> previous;
  for (std::size_t i = n - 11; i + 1 < n; ++i) previous.push_back(r.history[i].increment);
  std::nth_element(previous.begin(), previous.begin() + 5, previous.end());
  const double median = previous[5];
  const double last = r.history[n - 1].increment;
  const double before = std::max({r.history[n - 2].increment, r.history[n - 3].increment, r.history[n - 4].increment});
  if (median <= 5 * tol || last >= 0.1 * before) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "the increments had not settled (median of the ten before the last %.2e, tol %g) and "
                "fell abruptly (largest of the three before the last %.2e, the last %.2e): the stop may "
                "be a chance dip below tol; see history.csv",
                median, tol, before, last);
  return text;
}

CouplingResult FixedPointCoupling::run() {
  H_.structure().begin();
  return window(initial);
}

CouplingResult FixedPointCoupling::next_window(const Eigen::VectorXd& u_start) {
  relaxation_.end_window();
  return window(u_start);
}

CouplingResult FixedPointCoupling::window(const Eigen::VectorXd& u0) {
  FixedPointLoop loop(H_, relaxation_, M_, tol_, max_iterations_);
  loop.progress = progress;
  loop.observe = observe;
  loop.inexact_fraction = inexact_fraction;
  return loop.run(u0);
}

}  // namespace fsi
