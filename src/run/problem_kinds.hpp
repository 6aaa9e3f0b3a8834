// The kinds of run (run/problem.hpp), each defined in its own file, and make_problem,
// which picks one.
#pragma once

#include <memory>

#include "run/problem.hpp"

namespace fsi {

// The kind of run the case asks for: contact alone (no [fluid]), the fluid alone
// (structure.shape = "none"), or the fluid around the structure at rest
// (coupling.max_iterations = 0) or coupled to it (SPEC §5), by fluid.method. Builds
// nothing yet.
std::unique_ptr<Problem> make_problem(const Case& c, const RunOptions& options);

// SPEC §2: no [fluid] (run/contact_problem.cpp).
std::unique_ptr<Problem> contact_problem(const Case& c, const RunOptions& options);
// [time] without [fluid]: the structure alone in time (run/time_structure_problem.cpp).
std::unique_ptr<Problem> time_structure_problem(const Case& c, const RunOptions& options);
// structure.shape = "none": the fluid alone, no structure (run/fluid_problem.cpp).
std::unique_ptr<Problem> fluid_problem(const Case& c, const RunOptions& options);
// [time] with structure.shape = "none": the fluid alone in time (run/time_fluid_problem.cpp).
std::unique_ptr<Problem> time_fluid_problem(const Case& c, const RunOptions& options);
// fluid.method = "penalised" (run/penalised_problem.cpp): coupled (SPEC §5), or with
// coupling.max_iterations = 0 the fluid alone around the structure at rest (SPEC §3).
std::unique_ptr<Problem> penalised_fsi(const Case& c, const RunOptions& options);
std::unique_ptr<Problem> penalised_fluid_at_rest(const Case& c, const RunOptions& options);
// [time] with a structure and a penalised fluid: the coupled problem in time (run/time_fsi_problem.cpp).
std::unique_ptr<Problem> time_penalised_fsi(const Case& c, const RunOptions& options);
// fluid.method = "body-fitted" (run/body_fitted_problem.cpp): the same two kinds.
std::unique_ptr<Problem> body_fitted_fsi(const Case& c, const RunOptions& options);
std::unique_ptr<Problem> body_fitted_fluid_at_rest(const Case& c, const RunOptions& options);

}  // namespace fsi
