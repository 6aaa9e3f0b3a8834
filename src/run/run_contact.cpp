// The contact-only problem (SPEC §2): one QP.
#include <cmath>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/fault.hpp"
#include "io/atomic_file.hpp"
#include "run/contact_gap.hpp"
#include "run/output_dir.hpp"
#include "run/probes.hpp"
#include "run/run_case.hpp"
#include "run/structure_outputs.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

std::string contact_report(const Case& c, const MeshStatistics& stats, const StructureSetup& s,
                           const ContactSolution& solution, const ContactSummary& contact, double max_u, double min_u2) {
  char text[1024];
  const std::string zone = contact.active_nodes
                               ? "Contact on " + std::to_string(contact.active_nodes) + " node(s), X1 in [" +
                                     approx(contact.x_min, 6) + ", " + approx(contact.x_max, 6) +
                                     "] m, peak pressure " + approx(contact.max_multiplier, 6) + " Pa."
                               : "No contact.";
  std::snprintf(text, sizeof text,
                "%s: contact problem on %d triangles / %d vertices, solved by %s in %d iteration(s) (largest KKT "
                "residual %.1e). Max displacement %.4g m, lowest u2 %.4g m. %s Results in %s/ (summary.json%s%s).",
                c.name.c_str(), stats.triangles, stats.vertices, s.qp->name().c_str(), solution.qp.iterations,
                solution.qp.kkt.max(), max_u, min_u2, zone.c_str(), c.output.dir.c_str(),
                c.output.vtu ? ", structure.vtu" : "", c.output.png ? ", structure.png" : "");
  return text;
}

}  // namespace

RunResult run_contact_case(const Case& c, const RunOptions& options) {
  PhaseTimes times;
  const Stopwatch total;
  auto progress = [&](const std::string& line) {
    if (options.progress) options.progress("[structure] " + line);
  };
  Mesh mesh;
  {
    ScopedPhase phase(times, "mesh");
    mesh = make_structure_mesh(c);
    fault_point("mesh");
  }
  const MeshStatistics stats = statistics(mesh);

  StructureSetup s;
  ContactSolution solution;
  {
    ScopedPhase phase(times, "structure");
    s = make_structure(c, std::move(mesh), progress);
    fault_point("structure");
    try {
      fault_point("contact");
      solution = s.gap->solve(*s.solver, s.b_applied);
    } catch (const QpError& e) {
      throw SolverFailure(std::string("structure: contact QP failed: ") + e.what());
    }
  }
  // A non-finite answer is a failure, never a "converged" result.
  if (!solution.u.allFinite() || !solution.qp.alpha.allFinite())
    throw SolverFailure("structure: the contact QP returned a non-finite displacement or multiplier");
  const ContactSummary contact = summarize_contact(*s.solver, solution);
  const Eigen::VectorXd u1 = component(solution.u, 0), u2 = component(solution.u, 1);
  const double max_u = max_displacement(solution.u);

  RunResult r;
  RunMeasures& m = r.measures;
  m.structure_mesh = stats;
  m.converged = true;
  m.status = "converged";
  m.iterations = solution.qp.iterations;
  m.displacement = RunMeasures::Displacement{max_u, u2.minCoeff()};
  m.contact = contact;
  Json& j = r.summary;
  j = summary_header(c);
  j["mesh"] = {{"structure", to_json(stats)}};
  add_measures(j, m);
  j["solver"] = s.qp->name();
  j["qp_status"] = solution.qp.status;
  j["tip_displacement"] = tip_displacement_json(c, s.mesh(), solution.u, s.p2());
  add_displacement_at(j, c, s.mesh(), solution.u, s.p2());
  j["contact"] = to_json(contact);
  add_gap_summary(j["contact"], c, s, solution);
  j["contact"]["linearisations"] = s.gap->linearisations();
  j["kkt"] = to_json(solution.qp.kkt);
  if (c.structure.model != "linear") j["newton"] = newton_json(solution.newton);
  r.report = contact_report(c, stats, s, solution, contact, max_u, u2.minCoeff());

  write_outputs(
      c, r,
      [&](RunOutputs& out) {
        ScopedPhase phase(times, "output");
        if (c.output.vtu)
          out.write("structure.vtu",
                    [&](const std::string& p) { write_structure_vtu(p, c, s, solution, false); });
        if (c.output.png) out.write("structure.png", [&](const std::string& p) { write_structure_png(p, c, s, solution); });
        out.write("case.toml", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << to_toml(c); }); });
      },
      [&](Json& summary) { finish_timing(summary, r.measures, times, total); });
  return r;
}

}  // namespace fsi
