// The two kinds of penalised run: the coupled problem (SPEC §5) and the fluid alone
// around the structure at rest (coupling.max_iterations = 0, SPEC §3).
#include <cstdio>

#include "common/format.hpp"
#include "coupling/fixed_point.hpp"
#include "coupling/penalised_step.hpp"
#include "run/outputs/coupling_outputs.hpp"
#include "run/penalised_problem.hpp"
#include "fem/probes.hpp"
#include "run/problem_kinds.hpp"
#include "run/region_hint.hpp"
#include "run/steady_start.hpp"

namespace fsi {
namespace {

class PenalisedFsi final : public PenalisedProblem {
 public:
  using PenalisedProblem::PenalisedProblem;

  // The fixed point of SPEC §5 from rest (or from options.initial_displacement), its
  // passes' phases timed.
  void solve(PhaseTimes& times) override {
    result_ = couple();
    for (const auto& r : result_.history) {
      times.add("fluid", r.t_fluid);
      times.add("structure", r.t_structure);
      times.add("transfer", r.t_transfer);
      times.add("chi", r.t_chi);
    }
    complete_fluid();
  }

 private:
  CouplingResult couple() {
    const Mesh& ref = s_->mesh();
    StructureStep structure(*s_->solver, s_->gap.get());
    const ProbeSet probes(ref, c_.output.probes, s_->p2());
    if (options_.initial_displacement) f_->stokes->continue_last_run();  // the kept near region may serve the start's χ
    expect_structure_under_loads(*s_, *f_);
    return couple_steady(c_, ref, *f_, fluid_force(), structure, s_->b_applied, [&](FixedPointCoupling& loop) {
      loop.progress = [this](const std::string& line) {
        if (options_.progress) options_.progress(line);
      };
      loop.observe = probe_observer(probes);  // history.csv's u_x_i, u_y_i
      if (options_.initial_displacement) loop.initial = *options_.initial_displacement;
    });
  }

  void measure_structure(RunMeasures& m) override { measure_coupled_structure(m); }
  void summarise_structure(Json& j, const RunMeasures& m) override { summarise_coupled_structure(j, m); }
  void write_structure(RunOutputs& out, bool fluid_vtu_written) override {
    write_coupled_files(out, c_, *s_, result_, fluid_ != nullptr, fluid_vtu_written, false);
  }
  const char* picture_name() const override { return "fsi.png"; }
  std::string picture_state() const override { return passes_note(); }
  std::vector<int> contact_vertices() const override { return active_vertices(*s_->solver, result_.structure); }

  std::string report(const RunMeasures& m) const override {
    const RunMeasures::FluidInStructure& n = *m.fluid_in_structure;
    const ContactSummary cs = m.contact.value_or(ContactSummary{});
    const std::string zone =
        cs.active_nodes ? ", X1 in [" + approx(cs.x_min, 6) + ", " + approx(cs.x_max, 6) + "] m" : "";
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: %s after %d fixed-point iterations (%s, last increment %.4e, tol %g). |v| in the structure "
                  "%.5g, |v|/eps %.6g. Max displacement %.4g m; contact on %d node(s)%s. Fluid %d triangles, "
                  "structure %d. Results in %s/.",
                  c_.name.c_str(), result_.converged ? "converged" : "NOT converged", result_.iterations,
                  c_.coupling.scheme.c_str(), result_.final_increment, c_.coupling.tol, n.v, n.v / c_.coupling.eps,
                  m.displacement->max, cs.active_nodes, zone.c_str(), m.fluid_mesh.triangles,
                  m.structure_mesh.triangles, c_.output.dir.c_str());
    std::string report = text;
    if (!m.convergence_warning.empty()) report += " Warning: " + m.convergence_warning + ".";
    return report;
  }
};

// One solve around the structure at rest, and its force on the structure (eq. 33 at
// u = 0); the structure itself is not solved.
class PenalisedFluidAtRest final : public PenalisedProblem {
 public:
  using PenalisedProblem::PenalisedProblem;
  const char* kind() const override { return "fluid"; }

  void solve(PhaseTimes& times) override {
    const Stopwatch clock;
    const FluidSolution& v = solve_fluid_once(*f_->stokes, (*f_->chi)(s_->mesh()));
    times.add("fluid", clock.elapsed());
    result_.structure = s_->solver->at_rest();
    result_.converged = true;
    const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2 * s_->mesh().num_vertices());
    const FluidForce force = fluid_force();
    result_.fluid_load = force(
        sample_at_deformed_vertices(FluidField(*f_->locator, v), force.sample_mesh(), force.to_samples(rest)), rest);
    complete_fluid();
  }

 private:
  void measure_structure(RunMeasures&) override {}
  void summarise_structure(Json&, const RunMeasures&) override {}
  void write_structure(RunOutputs&, bool) override {}
  const char* picture_name() const override { return "fluid.png"; }
  std::string picture_state() const override { return "structure at rest"; }
  std::vector<int> contact_vertices() const override { return {}; }

  std::string report(const RunMeasures& m) const override {
    const RunMeasures::FluidInStructure& n = *m.fluid_in_structure;
    const PenalisedStokes& stokes = *f_->stokes;
    const FluidTiming& t = stokes.timing();
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: fluid alone around the structure at rest: %d unknowns on %d triangles, solved in %.3f s (%s). "
                  "|v| in the structure %.4e (eps %g, |v|/eps %.4g). Results in %s/ (summary.json%s%s).",
                  c_.name.c_str(), stokes.unknowns(), m.fluid_mesh.triangles, t.factorization + t.solve + t.assembly,
                  stokes.solver_name().c_str(), n.v, c_.coupling.eps, n.v / c_.coupling.eps, c_.output.dir.c_str(),
                  c_.output.vtu ? ", fluid.vtu" : "", c_.output.png ? ", fluid.png" : "");
    return text;
  }
};

}  // namespace

std::unique_ptr<Problem> penalised_fsi(const Case& c, const RunOptions& options) {
  return std::make_unique<PenalisedFsi>(c, options);
}

std::unique_ptr<Problem> penalised_fluid_at_rest(const Case& c, const RunOptions& options) {
  return std::make_unique<PenalisedFluidAtRest>(c, options);
}

}  // namespace fsi
