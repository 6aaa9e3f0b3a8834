#include "run/coupling_outputs.hpp"

#include <iomanip>

#include "common/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

namespace {

// output.probes's columns (SPEC §11): ũ at probe i as u_x_i,u_y_i, counted from 1; in
// max_digits10 so that a converged run's last row is summary.json's displacement_at.
void write_probe_header(std::ostream& out, std::size_t probes) {
  for (std::size_t i = 1; i <= probes; ++i) out << ",u_x_" << i << ",u_y_" << i;
}

void write_probes(std::ostream& out, const std::vector<Point>& u) {
  const std::streamsize precision = out.precision(17);
  for (const Point& d : u) out << ',' << d.x() << ',' << d.y();
  out.precision(precision);
}

}  // namespace

void write_history(const std::string& path, const std::vector<IterationRecord>& history,
                   bool body_fitted) {
  write_atomically(path, [&](std::ostream& out) {
    out << "iteration,increment_l2,omega,active_nodes,chi_triangles,fluid_reused,t_chi_s,t_fluid_s,"
           "t_transfer_s,t_structure_s"
        << (body_fitted ? ",fluid_triangles,remeshed,t_mesh_s" : "") << ",newton_steps";
    write_probe_header(out, history.empty() ? 0 : history.front().probes.size());
    out << '\n' << std::setprecision(10);
    for (const auto& r : history) {
      out << r.iteration << ',' << r.increment << ',' << r.omega << ',' << r.active_nodes << ','
          << r.chi_triangles << ',' << (r.fluid_reused ? 1 : 0) << ',' << r.t_chi << ','
          << r.t_fluid << ',' << r.t_transfer << ',' << r.t_structure;
      if (body_fitted)
        out << ',' << r.fluid_triangles << ',' << (r.remeshed ? 1 : 0) << ',' << r.t_mesh;
      out << ',' << r.newton_steps;
      write_probes(out, r.probes);
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

int exit_status_of(const CouplingResult& r) {
  return !r.failure.empty() ? 1 : r.interrupted ? interrupted_exit_status() : r.converged ? 0 : 3;
}

RunMeasures coupled_measures(const Case& c, const CouplingResult& r, bool fluid_only) {
  RunMeasures m;
  m.converged = r.converged;
  m.status = status_of(r);
  m.failure = r.failure;
  m.convergence_warning = convergence_warning(r, c.coupling.tol);
  m.iterations = r.iterations;
  if (!fluid_only) m.stop = RunMeasures::Stop{r.iterations - 1, r.final_increment, r.final_norm};
  m.displacement = RunMeasures::Displacement{max_displacement(r.structure.u), component(r.structure.u, 1).minCoeff()};
  return m;
}

}  // namespace fsi
