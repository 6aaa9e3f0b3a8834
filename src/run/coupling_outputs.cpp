#include "run/coupling_outputs.hpp"

#include <iomanip>

#include "io/atomic_file.hpp"

namespace fsi {

void write_history(const std::string& path, const std::vector<IterationRecord>& history,
                   bool body_fitted) {
  write_atomically(path, [&](std::ostream& out) {
    out << "iteration,increment_l2,omega,active_nodes,chi_triangles,fluid_reused,t_chi_s,t_fluid_s,"
           "t_transfer_s,t_structure_s"
        << (body_fitted ? ",fluid_triangles,remeshed,t_mesh_s" : "") << '\n'
        << std::setprecision(10);
    for (const auto& r : history) {
      out << r.iteration << ',' << r.increment << ',' << r.omega << ',' << r.active_nodes << ','
          << r.chi_triangles << ',' << (r.fluid_reused ? 1 : 0) << ',' << r.t_chi << ','
          << r.t_fluid << ',' << r.t_transfer << ',' << r.t_structure;
      if (body_fitted)
        out << ',' << r.fluid_triangles << ',' << (r.remeshed ? 1 : 0) << ',' << r.t_mesh;
      out << '\n';
    }
  });
}

const char* status_of(const CouplingResult& r) {
  return !r.failure.empty() ? "failed"
         : r.interrupted    ? "interrupted"
         : r.converged      ? "converged"
                            : "iteration limit";
}

}  // namespace fsi
