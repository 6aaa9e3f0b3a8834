// The coupled problem (SPEC §5) and, with coupling.max_iterations = 0, the fluid
// alone around the undeformed structure (SPEC §3).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <future>
#include <iomanip>
#include <optional>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "coupling/fixed_point.hpp"
#include "io/atomic_file.hpp"
#include "io/figure.hpp"
#include "io/vtu.hpp"
#include "run/contact_gap.hpp"
#include "run/coupling_outputs.hpp"
#include "run/fluid_band.hpp"
#include "run/fluid_outputs.hpp"
#include "run/fluid_setup.hpp"
#include "run/obstacle_forces.hpp"
#include "run/output_dir.hpp"
#include "run/probes.hpp"
#include "run/region_hint.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/structure_outputs.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

const char* velocity_png_name(bool fluid_only) {
  return fluid_only ? "fluid.png" : "fsi.png";
}

// ‖v_h‖ over the fluid triangles where χ = 1 (the region the penalty acts on).
double velocity_l2_on_chi(const FluidField& field, const Mesh& fluid_mesh, const Eigen::VectorXd& chi) {
  Mesh region;
  region.vertices = fluid_mesh.vertices;
  for (int t = 0; t < fluid_mesh.num_triangles(); ++t)
    if (chi[t] >= 1.0) region.triangles.push_back(fluid_mesh.triangles[t]);
  return velocity_l2_over(field, region);
}

// eq. (33)'s fluid terms, with the case's fluid and ε, on the reference mesh.
// Eq. (33) or its pull-back, on the structure's P1 mesh or its P2 space (the fields
// sampled at the nodal mesh's vertices, which are the P2 nodes).
FluidForce fluid_force_of(const Case& c, const StructureSetup& s) {
  const Point f_F = c.fluid->f;
  const auto f = [f_F](const Point&) { return f_F; };
  const ForceModel model = c.coupling.force == "large" ? ForceModel::large : ForceModel::small;
  if (s.p2()) return FluidForce(*s.p2(), c.fluid->mu, c.coupling.eps, f, model);
  return FluidForce(s.mesh(), c.fluid->mu, c.coupling.eps, f, model, c.coupling.force_sampling);
}

// The fluid alone around the structure at rest: one solve, and its force on the
// structure (eq. 33 at u = 0).
CouplingResult solve_fluid_alone(const Case& c, StructureSetup& s, FluidSetup& f, PhaseTimes& times) {
  const Stopwatch clock;
  const FluidSolution& v = solve_fluid_once(*f.stokes, (*f.chi)(s.mesh()));
  times.add("fluid", clock.elapsed());
  CouplingResult result;
  result.structure = s.solver->at_rest();
  result.converged = true;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2 * s.mesh().num_vertices());
  const FluidForce force = fluid_force_of(c, s);
  result.fluid_load =
      force(sample_at_deformed_vertices(FluidField(*f.locator, v), force.sample_mesh(), force.to_samples(rest)), rest);
  return result;
}

CouplingResult couple(const Case& c, StructureSetup& s, FluidSetup& f, PhaseTimes& times,
                      const std::function<void(const std::string&)>& progress, const Eigen::VectorXd* initial) {
  const Mesh& ref = s.mesh();
  const FluidForce force = fluid_force_of(c, s);
  auto relaxation = make_relaxation(c.coupling.scheme, {.omega0 = c.coupling.omega}, assemble_vector_mass(ref));
  FixedPointCoupling loop({*s.solver, s.b_applied, *f.stokes, *f.locator, *f.chi, force}, *relaxation,
                          c.coupling.tol, c.coupling.max_iterations);
  loop.progress = progress;
  const ProbeSet probes(ref, c.output.probes, s.p2());
  loop.observe = probes.observer();  // history.csv's u_x_i, u_y_i
  if (initial) {
    loop.initial = *initial;
    f.stokes->continue_last_run();  // the kept near region may serve the start's χ
  }
  const ContactGap& gap = *s.gap;
  if (gap.normal()) {
    // From the linearisation at rest, whatever a cached setup's last run left (a sweep's
    // row must give the numbers of a run of its own).
    gap.relinearise(*s.solver, Eigen::VectorXd::Zero(2 * ref.num_vertices()));
    loop.relinearise = [&gap, &s](const Eigen::VectorXd& u) { gap.relinearise(*s.solver, u); };
  }
  expect_structure_under_loads(s, f);
  CouplingResult result = loop.run();
  for (const auto& r : result.history) {
    times.add("fluid", r.t_fluid);
    times.add("structure", r.t_structure);
    times.add("transfer", r.t_transfer);
    times.add("chi", r.t_chi);
  }
  return result;
}

// ‖v_h‖ over the deformed structure and over χ = 1. The norms read the fields in the
// fluid triangles those meet only, which a solution exact near the structure holds;
// if the structure reaches beyond it, the solution is completed first. `failure`
// says why they are missing.
struct FluidNorms {
  double v = NAN, v_chi = NAN;
  std::string failure;
};

FluidNorms fluid_norms(FluidSetup& f, const Mesh& deformed) {
  FluidNorms n;
  if (!f.stokes->has_solution()) return n;
  const Eigen::VectorXd& chi = f.stokes->last_solution_chi();
  std::vector<int> read = triangles_meeting(*f.locator, deformed);
  for (int t = 0; t < f.mesh->num_triangles(); ++t)
    if (chi[t] >= 1.0) read.push_back(t);
  try {
    const FluidField field(*f.locator, f.stokes->solution(&read));
    n.v = velocity_l2_over(field, deformed);
    n.v_chi = velocity_l2_on_chi(field, *f.mesh, chi);
  } catch (const SolverFailure& e) {
    n.failure = e.what();
  }
  return n;
}


std::string fsi_report(const Case& c, const CouplingResult& result, const RunMeasures& m,
                       const PenalisedStokes& stokes, bool fluid_only) {
  const RunMeasures::FluidInStructure& n = *m.fluid_in_structure;
  const MeshStatistics &s_stats = m.structure_mesh, &f_stats = m.fluid_mesh;
  const ContactSummary cs = m.contact.value_or(ContactSummary{});
  const double max_u = m.displacement->max;
  char text[1024];
  if (fluid_only) {
    const FluidTiming& t = stokes.timing();
    std::snprintf(text, sizeof text,
                  "%s: fluid alone around the structure at rest: %d unknowns on %d triangles, solved in %.3f s (%s). "
                  "|v| in the structure %.4e (eps %g, |v|/eps %.4g). Results in %s/ (summary.json%s%s).",
                  c.name.c_str(), stokes.unknowns(), f_stats.triangles, t.factorization + t.solve + t.assembly,
                  stokes.solver_name().c_str(), n.v, c.coupling.eps, n.v / c.coupling.eps, c.output.dir.c_str(),
                  c.output.vtu ? ", fluid.vtu" : "", c.output.png ? ", fluid.png" : "");
    return text;
  }
  const std::string zone =
      cs.active_nodes ? ", X1 in [" + approx(cs.x_min, 6) + ", " + approx(cs.x_max, 6) + "] m" : "";
  std::snprintf(text, sizeof text,
                "%s: %s after %d fixed-point iterations (%s, last increment %.4e, tol %g). |v| in the structure "
                "%.5g, |v|/eps %.6g. Max displacement %.4g m; contact on %d node(s)%s. Fluid %d triangles, "
                "structure %d. Results in %s/.",
                c.name.c_str(), result.converged ? "converged" : "NOT converged", result.iterations,
                c.coupling.scheme.c_str(), result.final_increment, c.coupling.tol, n.v, n.v / c.coupling.eps, max_u,
                cs.active_nodes, zone.c_str(), f_stats.triangles, s_stats.triangles, c.output.dir.c_str());
  std::string report = text;
  if (!m.convergence_warning.empty()) report += " Warning: " + m.convergence_warning + ".";
  return report;
}


// Set up: the meshes, the structure, fluid.band's box (around the structure's
// load-alone solution: after the structure) and the fluid, each timed as its phase.
struct FsiSetup {
  StructureSetup& s;
  FluidSetup& f;
  std::optional<std::array<double, 4>> band;
  MeshStatistics s_stats, f_stats;
};

// Whether the structure can be meshed and set up while the box is meshed: both
// meshes from the generator (Gmsh runs in a forked child, which must not share the
// process with a second thread), and a box that does not depend on the structure
// (no band around its load-alone solution).
bool meshes_apart(const Case& c) {
  return c.structure.rectangle() && c.structure.mesher == "lattice" && c.fluid->mesh.empty() &&
         c.fluid->mesher == "lattice" && !band_needs_structure(c);
}

FsiSetup set_up(const Case& c, SetupCache& cache, PhaseTimes& times) {
  PhaseTimes structure_times;  // its own: PhaseTimes is not shared between threads
  const auto structure = [&] {
    const MeshStatistics stats =
        in_phase(structure_times, "mesh", [&] { return statistics(cache.structure_mesh(c)); });
    return std::pair(stats,
                     in_phase(structure_times, "structure", [&] { return &cache.structure(c); }));
  };
  // The structure on a second core where it can (~5 ms at hS = 0.015 beside the
  // box's ~20 ms at hF = 0.01), its phases timed there: they overlap the box's.
  std::future<std::pair<MeshStatistics, StructureSetup*>> apart;
  if (meshes_apart(c)) apart = std::async(std::launch::async | std::launch::deferred, structure);
  std::pair<MeshStatistics, StructureSetup*> s;
  if (!apart.valid()) s = structure();
  std::optional<std::array<double, 4>> band;
  MeshStatistics f_stats;
  try {
    band = in_phase(times, "mesh", [&] { return cache.band(c); });
    f_stats = in_phase(times, "mesh", [&] { return statistics(cache.fluid_mesh(c)); });
  } catch (...) {
    if (apart.valid()) apart.get();  // the structure's failure first, as if in turn
    throw;
  }
  if (apart.valid()) s = apart.get();
  for (const char* phase : {"mesh", "structure"}) times.add(phase, structure_times.get(phase));
  FluidSetup& f = *in_phase(times, "fluid", [&] { return &cache.fluid(c); });
  return {*s.second, f, band, s.first, f_stats};
}

// Measure: the final state (ũ: the solution if converged; after a failure the last
// good one) and the last successful fluid solution. A converged run with a quantity
// it cannot state is a failure, not an answer (set in `result`).
RunMeasures measure(const Case& c, FsiSetup& su, CouplingResult& result, const Mesh& deformed, bool fluid_only) {
  const FluidNorms norms = fluid_norms(su.f, deformed);
  const double max_u = max_displacement(result.structure.u);
  if (result.failure.empty() && !(std::isfinite(norms.v) && std::isfinite(norms.v_chi) && std::isfinite(max_u)))
    result.failure = "the final state is not finite (|v| in the structure " + std::to_string(norms.v) +
                     ", max displacement " + std::to_string(max_u) + ")" +
                     (norms.failure.empty() ? "" : ": " + norms.failure);
  if (!result.failure.empty()) result.converged = false;
  RunMeasures m = coupled_measures(c, result, fluid_only);
  m.structure_mesh = su.s_stats, m.fluid_mesh = su.f_stats;
  m.fluid_in_structure = RunMeasures::FluidInStructure{norms.v, norms.v / c.coupling.eps, norms.v_chi};
  if (!fluid_only) m.contact = summarize_contact(*su.s.solver, result.structure);
  return m;
}

// Summarise: summary.json's keys (SPEC §8, §9, §10).
Json fsi_summary(const Case& c, FsiSetup& su, const CouplingResult& result, const RunMeasures& m,
                 const Mesh& deformed, const RunOptions& options, bool fluid_only) {
  Json j = summary_header(c);
  j["mesh"] = {{"structure", to_json(m.structure_mesh)}, {"fluid", to_json(m.fluid_mesh)}};
  j["initial_state"] = options.initial_displacement ? "given" : "rest";
  if (su.band) {
    j["mesh"]["fluid"]["h_near"] = c.fluid->h_near;
    j["mesh"]["fluid"]["band_box"] = *su.band;
    j["mesh"]["fluid"]["band_warning"] =
        inside_band(deformed, *su.band, c.fluid->h_near)
            ? Json(nullptr)
            : Json("the structure's final configuration leaves the band refined to fluid.h_near: widen fluid.band");
  }
  add_measures(j, m);
  const StructureSetup& s = su.s;
  j["tip_displacement"] = tip_displacement_json(c, s.mesh(), result.structure.u, s.p2());
  add_displacement_at(j, c, s.mesh(), result.structure.u, s.p2());
  j["structure_force"] = point_json(resultant(result.fluid_load));
  j["structure_load"] = point_json(resultant_off(result.fluid_load, s.mesh(), s.mesh().label("Gamma_D")));
  if (!fluid_only) {
    j["contact"] = to_json(*m.contact);
    add_gap_summary(j["contact"], c, s, result.structure);
    j["kkt"] = to_json(result.structure.qp.kkt);
    if (c.structure.model != "linear") j["newton"] = newton_json(result.structure.newton);  // the last pass's
    j["relaxation"] = {{"scheme", c.coupling.scheme}, {"omega0", c.coupling.omega}, {"projections", result.projections}};
  }
  if (c.obstacles_given) j["obstacles"] = obstacle_forces_json(c, su.f);  // the fluid's force on each (SPEC §10)
  j["fluid"] = fluid_json(*su.f.stokes);
  return j;
}

// The last fluid solution everywhere, for the outputs that draw or write the whole
// fluid (the substructured solve leaves the far field until asked); null without them,
// or if that fails (said in result.failure).
const FluidSolution* fluid_everywhere(const Case& c, FluidSetup& f, CouplingResult& result) {
  if (!(c.output.png || c.output.vtu) || !f.stokes->has_solution()) return nullptr;
  try {
    return &f.stokes->solution();
  } catch (const SolverFailure& e) {
    if (result.failure.empty()) result.failure = std::string("the fluid solve (far field) failed: ") + e.what();
    return nullptr;
  }
}

// The velocity picture (fsi.png, or fluid.png for the fluid alone), drawn and encoded
// on a second thread as soon as the run is measured: it is the largest output (~35 ms
// at hF = 0.01), and it overlaps the summary and the other files. `fluid` is complete
// by then (fluid_everywhere), so the reads that follow (the obstacle forces) leave it
// unchanged. Not valid if no picture is asked for.
std::future<std::string> start_velocity_png(const Case& c, FsiSetup& su,
                                            const CouplingResult& result,
                                            const FluidSolution* fluid, const Mesh& deformed,
                                            bool fluid_only) {
  if (!(c.output.png && fluid)) return {};
  char note[256];
  std::snprintf(note, sizeof note, "eps = %g, omega = %g (%s), hF = %g, hS = %g;  %s",
                c.coupling.eps, c.coupling.omega, c.coupling.scheme.c_str(), c.fluid->h,
                c.structure.h,
                fluid_only ? "structure at rest"
                           : (std::to_string(result.iterations) + " iterations" +
                              (result.converged ? "" : " (not converged)"))
                                 .c_str());
  std::vector<int> contact =
      fluid_only ? std::vector<int>{} : active_vertices(*su.s.solver, result.structure);
  const Mesh& mesh = *su.f.mesh;
  return std::async(
      std::launch::async | std::launch::deferred,
      [&c, &mesh, fluid, &deformed, note = std::string(note), contact = std::move(contact),
       name = RunOutputs(c.output.dir).path(velocity_png_name(fluid_only))] {
        return fluid_png(name, c, mesh, *fluid, deformed, contact,
                         c.name + ": fluid velocity magnitude", note);
      });
}

// Write: the fields where they exist everywhere (`fluid`: null draws no fluid),
// history.csv, case.toml, and the velocity picture `png` (start_velocity_png) once
// it is drawn. The files themselves are written one at a time (an interrupted write
// removes its one temporary: common/interrupt.hpp).
void write_fsi_files(RunOutputs& out, const Case& c, FsiSetup& su, const CouplingResult& result,
                     const FluidSolution* fluid, std::future<std::string>& png, bool fluid_only) {
  StructureSetup& s = su.s;
  FluidSetup& f = su.f;
  if (c.output.vtu && fluid) {
    const bool fluid_vtu = out.write("fluid.vtu", [&](const std::string& p) {
      write_fluid_vtu(p, c, *f.mesh, *fluid, f.stokes->last_solution_chi());
    });
    if (!fluid_only) {
      const bool structure_vtu = out.write("structure.vtu", [&](const std::string& p) {
        write_structure_vtu(p, c, s, result.structure, true);
      });
      if (fluid_vtu && structure_vtu)  // never a .pvd that names a missing file
        out.write("fsi.pvd", [&](const std::string& p) { write_pvd(p, {{"fluid.vtu", 0}, {"structure.vtu", 1}}); });
    }
  }
  if (c.output.png && fluid && !fluid_only)
    out.write("structure.png", [&](const std::string& p) { write_structure_png(p, c, s, result.structure); });
  if (!fluid_only) out.write("history.csv", [&](const std::string& p) { write_history(p, result.history, false); });
  out.write("case.toml", [&](const std::string& p) { write_atomically(p, [&](std::ostream& o) { o << to_toml(c); }); });
  if (png.valid())
    out.write(velocity_png_name(fluid_only),
              [&](const std::string& p) { write_file_atomically(p, png.get()); });
}

}  // namespace

// Set up → solve → measure → summarise → write (the shape of a deal.II tutorial's run()).
RunResult run_fsi_case(const Case& c, const RunOptions& options) {
  if (c.structure.shape == "none") return run_fluid_case(c, options);
  if (c.fluid->method == "body-fitted") return run_body_fitted_case(c, options);
  PhaseTimes times;
  const Stopwatch total;
  // The figures' fonts, loaded on the second core while the run meshes and solves.
  const std::future<void> fonts =
      c.output.png ? std::async(std::launch::async | std::launch::deferred, load_figure_fonts)
                   : std::future<void>{};
  SetupCache local_cache;
  FsiSetup su = set_up(c, options.cache ? *options.cache : local_cache, times);
  const bool fluid_only = c.coupling.max_iterations == 0;
  auto progress = [&options](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  CouplingResult result = fluid_only ? solve_fluid_alone(c, su.s, su.f, times)
                                     : couple(c, su.s, su.f, times, progress, options.initial_displacement);
  const FluidSolution* fluid = fluid_everywhere(c, su.f, result);

  const Eigen::VectorXd& u = result.structure.u;
  const Mesh deformed = displaced(su.s.mesh(), component(u, 0), component(u, 1));
  RunResult r;
  // The measures may find the run failed: before the picture's note says how it ended.
  r.measures = measure(c, su, result, deformed, fluid_only);
  std::future<std::string> png = start_velocity_png(c, su, result, fluid, deformed, fluid_only);
  r.displacement = u;
  r.summary = fsi_summary(c, su, result, r.measures, deformed, options, fluid_only);
  r.report = fsi_report(c, result, r.measures, *su.f.stokes, fluid_only);
  r.exit_status = exit_status_of(result);
  if (!result.failure.empty()) r.failure = result.failure + " (the last good state is written in " + c.output.dir + "/)";
  auto files = [&](RunOutputs& out) {
    ScopedPhase phase(times, "output");
    write_fsi_files(out, c, su, result, fluid, png, fluid_only);
  };
  write_outputs(c, r, files, [&](Json& summary) { finish_timing(summary, r.measures, times, total); });
  return r;
}

}  // namespace fsi
