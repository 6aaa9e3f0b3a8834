#include "run/problem_kinds.hpp"

namespace fsi {

std::unique_ptr<Problem> make_problem(const Case& c, const RunOptions& options) {
  if (!c.fluid) return c.time ? time_structure_problem(c, options) : contact_problem(c, options);
  if (c.structure.shape == "none") return c.time ? time_fluid_problem(c, options) : fluid_problem(c, options);
  const bool at_rest = c.coupling.max_iterations == 0;
  if (c.fluid->method == "body-fitted")
    return at_rest ? body_fitted_fluid_at_rest(c, options) : body_fitted_fsi(c, options);
  if (c.time) return time_penalised_fsi(c, options);
  return at_rest ? penalised_fluid_at_rest(c, options) : penalised_fsi(c, options);
}

}  // namespace fsi
