#include "run/outputs/structure_history.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"
#include "io/atomic_file.hpp"

namespace fsi {
namespace {

double total(const StructureRow& r) { return r.kinetic + r.elastic - r.work; }

}  // namespace

StructureRow structure_row(const NewmarkState& s, const Newmark& newmark, const StructureSetup& setup,
                           const ProbeSet* probes, double work, int qp_iterations) {
  StructureRow r;
  r.step = s.step;
  r.t = s.t;
  r.qp_iterations = qp_iterations;
  r.active_nodes = s.contact.qp.active_count();
  r.max_u = max_displacement(s.u);
  r.kinetic = newmark.kinetic_energy(s.v);
  r.elastic = elastic_energy(*setup.solver, s.u);
  r.work = work;
  r.velocity = newmark.momentum(s.v) / newmark.mass();
  if (s.contact.qp.alpha.size()) r.contact_force = resultant(setup.solver->contact().C_S.transpose() * s.contact.qp.alpha);
  if (probes && !probes->empty()) r.probes = probes->displacements(s.u);
  return r;
}

void write_structure_history(const std::string& path, const StructureRow& initial, const std::vector<StructureRow>& rows) {
  write_atomically(path, [&](std::ostream& out) {
    const bool coupled = initial.passes >= 0;
    out << "step,t,qp_iterations,active_nodes,max_u,kinetic,elastic,work,energy_error,vx,vy,contact_fx,contact_fy";
    if (coupled) out << ",passes,fluid_fx,fluid_fy";
    for (std::size_t i = 1; i <= initial.probes.size(); ++i) out << ",probe_" << i << "_ux,probe_" << i << "_uy";
    out << "\n";
    const double e0 = total(initial);
    const auto line = [&](const StructureRow& r) {
      out << r.step << "," << shortest(r.t) << "," << r.qp_iterations << "," << r.active_nodes << "," << shortest(r.max_u)
          << "," << shortest(r.kinetic) << "," << shortest(r.elastic) << "," << shortest(r.work) << ","
          << shortest(total(r) - e0) << "," << shortest(r.velocity.x()) << "," << shortest(r.velocity.y()) << ","
          << shortest(r.contact_force.x()) << "," << shortest(r.contact_force.y());
      if (coupled) out << "," << r.passes << "," << shortest(r.fluid_force.x()) << "," << shortest(r.fluid_force.y());
      for (const Point& p : r.probes) out << "," << shortest(p.x()) << "," << shortest(p.y());
      out << "\n";
    };
    line(initial);
    for (const StructureRow& r : rows) line(r);
  });
}

Json energy_json(const StructureRow& initial, const std::vector<StructureRow>& rows) {
  const double e0 = total(initial);
  double scale = initial.kinetic + initial.elastic, drift = 0, drift_t = initial.t;
  for (const StructureRow& r : rows) {
    scale = std::max(scale, r.kinetic + r.elastic);
    if (std::abs(total(r) - e0) > std::abs(drift)) drift = total(r) - e0, drift_t = r.t;
  }
  const StructureRow& last = rows.empty() ? initial : rows.back();
  return {{"initial", e0},
          {"final", total(last)},
          {"kinetic", last.kinetic},
          {"elastic", last.elastic},
          {"work", last.work},
          {"max_drift", drift},
          {"max_drift_time", drift_t},
          {"max_relative_drift", scale > 0 ? std::abs(drift) / scale : 0.0}};
}

Json contact_intervals_json(const StructureRow& initial, const std::vector<StructureRow>& rows, double dt) {
  Json list = Json::array();
  for (std::size_t k = 0; k < rows.size();) {
    if (!rows[k].active_nodes) {
      ++k;
      continue;
    }
    std::size_t end = k, peak = k;
    while (end + 1 < rows.size() && rows[end + 1].active_nodes) {
      ++end;
      if (rows[end].contact_force.norm() > rows[peak].contact_force.norm()) peak = end;
    }
    const StructureRow& before = k ? rows[k - 1] : initial;
    const bool left = end + 1 < rows.size();
    list.push_back({{"start", rows[k].t},
                    {"end", rows[end].t},
                    {"duration", rows[end].t - rows[k].t + dt},
                    {"peak_force", rows[peak].contact_force.norm()},
                    {"peak_time", rows[peak].t},
                    {"velocity_before", point_json(before.velocity)},
                    {"velocity_after", left ? point_json(rows[end + 1].velocity) : Json(nullptr)}});
    k = end + 1;
  }
  return list;
}

}  // namespace fsi
