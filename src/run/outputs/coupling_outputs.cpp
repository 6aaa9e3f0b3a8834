#include "run/outputs/coupling_outputs.hpp"

#include <iomanip>

#include "common/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "fem/probes.hpp"
#include "run/outputs/structure_outputs.hpp"
#include "run/outputs/summary.hpp"
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

RunMeasures coupled_measures(const Case& c, const CouplingResult& r) {
  RunMeasures m;
  m.converged = r.converged;
  m.status = status_of(r);
  m.failure = r.failure;
  m.convergence_warning = convergence_warning(r, c.coupling.tol);
  m.iterations = r.iterations;
  m.displacement = RunMeasures::Displacement{max_displacement(r.structure.u), component(r.structure.u, 1).minCoeff()};
  return m;
}

PassObserver probe_observer(const ProbeSet& probes) {
  if (probes.empty()) return nullptr;
  return [&probes](const Eigen::VectorXd& u_tilde, IterationRecord& rec) { rec.probes = probes.displacements(u_tilde); };
}

RunMeasures::Stop coupled_stop(const CouplingResult& r) {
  return {r.iterations - 1, r.final_increment, r.final_norm};
}

void add_structure_displacements(Json& j, const Case& c, const StructureSetup& s, const CouplingResult& r) {
  j["tip_displacement"] = tip_displacement_json(c, s.mesh(), r.structure.u, s.p2());
  add_displacement_at(j, c, s.mesh(), r.structure.u, s.p2());
  j["structure_force"] = point_json(resultant(r.fluid_load));
  j["structure_load"] = point_json(resultant_off(r.fluid_load, s.mesh(), s.mesh().label("Gamma_D")));
}

void add_coupled_structure(Json& j, const Case& c, const StructureSetup& s, const CouplingResult& r,
                           const RunMeasures& m) {
  j["contact"] = to_json(*m.contact);
  add_gap_summary(j["contact"], c, s, r.structure);
  j["kkt"] = to_json(r.structure.qp.kkt);
  if (c.structure.model != "linear") j["newton"] = newton_json(r.structure.newton);  // the last pass's
  j["relaxation"] = {{"scheme", c.coupling.scheme}, {"omega0", c.coupling.omega}, {"projections", r.projections}};
}

void write_coupled_files(RunOutputs& out, const Case& c, const StructureSetup& s, const CouplingResult& r,
                         bool have_fluid, bool fluid_vtu_written, bool body_fitted, bool passes_history) {
  if (c.output.vtu && have_fluid) {
    const bool structure_vtu = out.write("structure.vtu", [&](const std::string& p) {
      write_structure_vtu(p, c, s, r.structure, true);
    });
    if (fluid_vtu_written && structure_vtu)
      out.write("fsi.pvd", [&](const std::string& p) { write_pvd(p, {{"fluid.vtu", 0}, {"structure.vtu", 1}}); });
  }
  if (c.output.png && have_fluid)
    out.write("structure.png", [&](const std::string& p) { write_structure_png(p, c, s, r.structure); });
  // A time run writes its own history.csv, one line a step (run/time_fsi_problem.cpp).
  if (passes_history) out.write("history.csv", [&](const std::string& p) { write_history(p, r.history, body_fitted); });
}

}  // namespace fsi
