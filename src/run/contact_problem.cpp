// The contact-only problem (SPEC §2): one QP.
#include <cmath>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/fault.hpp"
#include "io/atomic_file.hpp"
#include "solid/contact_gap.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/problem_kinds.hpp"
#include "fem/probes.hpp"
#include "run/run_case.hpp"
#include "run/outputs/structure_outputs.hpp"
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

// SPEC §2: the structure pressed against its obstacles by its own loads, one QP (or
// re-linearised QPs, contact.gap = "normal"; Newton's QPs for a nonlinear model).
class ContactProblem final : public Problem {
 public:
  ContactProblem(const Case& c, const RunOptions& options) : c_(c), options_(options) {}
  const char* kind() const override { return "contact"; }

  void set_up(PhaseTimes& times) override {
    Mesh mesh = in_phase(times, "mesh", [&] { return make_structure_mesh(c_); });
    stats_ = statistics(mesh);
    ScopedPhase phase(times, "structure");  // the set-up and the QP: one phase
    s_ = make_structure(c_, std::move(mesh), [this](const std::string& line) {
      if (options_.progress) options_.progress("[structure] " + line);
    });
    fault_point("structure");
  }

  void solve(PhaseTimes& times) override {
    ScopedPhase phase(times, "structure");
    try {
      fault_point("contact");
      solution_ = s_.gap->solve(*s_.solver, s_.b_applied);
    } catch (const QpError& e) {
      throw SolverFailure(std::string("structure: contact QP failed: ") + e.what());
    }
    // A non-finite answer is a failure, never a "converged" result.
    if (!solution_.u.allFinite() || !solution_.qp.alpha.allFinite())
      throw SolverFailure("structure: the contact QP returned a non-finite displacement or multiplier");
  }

  void measure(RunResult& r) override {
    RunMeasures& m = r.measures;
    m.structure_mesh = stats_;
    m.converged = true;
    m.status = "converged";
    m.iterations = solution_.qp.iterations;
    m.displacement = RunMeasures::Displacement{max_displacement(solution_.u), component(solution_.u, 1).minCoeff()};
    m.contact = summarize_contact(*s_.solver, solution_);
  }

  void summarise(RunResult& r) override {
    const RunMeasures& m = r.measures;
    Json& j = r.summary;
    j = summary_header(c_, kind());
    j["mesh"] = {{"structure", to_json(stats_)}};
    add_measures(j, m);
    j["solver"] = s_.qp->name();
    j["qp_status"] = solution_.qp.status;
    j["tip_displacement"] = tip_displacement_json(c_, s_.mesh(), solution_.u, s_.p2());
    add_displacement_at(j, c_, s_.mesh(), solution_.u, s_.p2());
    j["contact"] = to_json(*m.contact);
    add_gap_summary(j["contact"], c_, s_, solution_);
    j["contact"]["linearisations"] = s_.gap->linearisations();
    j["kkt"] = to_json(solution_.qp.kkt);
    if (c_.structure.model != "linear") j["newton"] = newton_json(solution_.newton);
    r.report = contact_report(c_, stats_, s_, solution_, *m.contact, m.displacement->max, m.displacement->min_y);
  }

  void final_fields(FinalFields& out) const override {
    out.structure = structure_arrays_if_solved(s_, solution_);
  }

  void write(RunOutputs& out) override {
    if (c_.output.vtu)
      out.write("structure.vtu", [&](const std::string& p) { write_structure_vtu(p, c_, s_, solution_, false); });
    if (c_.output.png)
      out.write("structure.png", [&](const std::string& p) { write_structure_png(p, c_, s_, solution_); });
    write_case_toml(out, c_);
  }

 private:
  const Case& c_;
  const RunOptions& options_;
  MeshStatistics stats_;
  StructureSetup s_;
  ContactSolution solution_;
};

}  // namespace

std::unique_ptr<Problem> contact_problem(const Case& c, const RunOptions& options) {
  return std::make_unique<ContactProblem>(c, options);
}

}  // namespace fsi
