#include <cstdio>
#include <filesystem>

#include "io/atomic_file.hpp"
#include "common/errors.hpp"
#include "run/output_dir.hpp"
#include "run/run_case.hpp"
#include "run/structure_outputs.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

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
  }
  const MeshStatistics stats = statistics(mesh);
  prepare_output_dir(c.output.dir, c.source);

  StructureSetup s;
  ContactSolution solution;
  {
    ScopedPhase phase(times, "structure");
    s = make_structure(c, std::move(mesh), progress);
    try {
      solution = s.solver->solve(s.b_applied);
    } catch (const QpError& e) {
      throw SolverFailure(std::string("structure: contact QP failed: ") + e.what());
    }
  }
  const ContactSummary contact = summarize_contact(*s.solver, solution);
  const Eigen::VectorXd u1 = component(solution.u, 0), u2 = component(solution.u, 1);
  const double max_displacement = (u1.array().square() + u2.array().square()).sqrt().maxCoeff();

  namespace fs = std::filesystem;
  const auto out = [&](const char* name) { return (fs::path(c.output.dir) / name).string(); };
  {
    ScopedPhase phase(times, "output");
    if (c.output.vtu) write_structure_vtu(out("structure.vtu"), s, solution, false);
    if (c.output.png) write_structure_png(out("structure.png"), c, s, solution);
    write_atomically(out("case.toml"), [&](std::ostream& o) { o << to_toml(c); });
  }

  RunResult r;
  Json& j = r.summary;
  j["name"] = c.name;
  j["problem"] = "contact";
  j["parameters"] = to_json(c);
  j["mesh"] = {{"structure", to_json(stats)}};
  j["converged"] = true;
  j["solver"] = s.qp->name();
  j["iterations"] = solution.qp.iterations;
  j["qp_status"] = solution.qp.status;
  j["max_displacement"] = max_displacement;
  j["min_displacement_y"] = u2.minCoeff();
  j["contact"] = to_json(contact);
  j["kkt"] = to_json(solution.qp.kkt);
  j["timing_s"] = timing_json(times, total.elapsed());
  write_json(out("summary.json"), j);

  char text[1024];
  std::snprintf(text, sizeof text,
                "%s: contact problem on %d triangles / %d vertices, solved by %s in %d "
                "iteration(s) (largest KKT residual %.1e). Max displacement %.4g m, lowest "
                "u2 %.4g m. %s Results in %s/ (summary.json%s%s).",
                c.name.c_str(), stats.triangles, stats.vertices, s.qp->name().c_str(),
                solution.qp.iterations, solution.qp.kkt.max(), max_displacement, u2.minCoeff(),
                contact.active_nodes
                    ? ("Contact on " + std::to_string(contact.active_nodes) + " node(s), X1 in [" +
                       std::to_string(contact.x_min) + ", " + std::to_string(contact.x_max) +
                       "] m, peak pressure " + std::to_string(contact.max_multiplier) + " Pa.")
                          .c_str()
                    : "No contact.",
                c.output.dir.c_str(), c.output.vtu ? ", structure.vtu" : "",
                c.output.png ? ", structure.png" : "");
  r.report = text;
  return r;
}

RunResult run_case(const Case& c, const RunOptions& options) {
  return c.fluid ? run_fsi_case(c, options) : run_contact_case(c, options);
}

}  // namespace fsi
