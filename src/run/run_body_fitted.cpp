// The coupled problem and the fluid alone with fluid.method = "body-fitted": the
// fluid on a mesh of D \ φ(Ω_S0) made for each fixed-point pass, no penalty
// (coupling/body_fitted_fluid.hpp). summary.json carries the keys of the penalised
// run that mean the same here (max_displacement, tip_displacement, structure_force,
// contact, kkt, timing_s, obstacles[i].force with [[obstacles]], ...), fluid.method and
// the meshing time of each pass; no ‖v‖ in the structure (v = 0 on Γ_u by
// construction) and no ε.
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/interrupt.hpp"
#include "coupling/body_fitted_coupling.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "mesh/mesh_error.hpp"
#include "run/coupling_outputs.hpp"
#include "run/fluid_outputs.hpp"
#include "run/fluid_setup.hpp"
#include "run/obstacle_forces.hpp"
#include "run/output_dir.hpp"
#include "run/probes.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/structure_outputs.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

BodyFittedFluidParams body_fitted_params(const Case& c) {
  const FluidParams& f = *c.fluid;
  const ObstacleParams& o = c.obstacle;
  BodyFittedFluidParams p;
  p.box = {f.L1, f.H1, f.H2, o.x0, o.y0, o.r, f.h};
  p.box.holes = case_holes(c);  // [[obstacles]]: each a hole Sigma_5_i (SPEC §9)
  // coupling.force = "large" is the exact traction on the deformed interface, as the
  // penalised method's exact pull-back; "small" the pressure with the reference normal,
  // as eq. (33) leaves it (body_fitted_force.hpp; the two differ by a model term,
  // docs/validation.md "The x load").
  p.normal = c.coupling.force == "large" ? PressureNormal::deformed : PressureNormal::reference;
  p.mu = f.mu;
  const Point f_F = f.f;
  p.f = [f_F](const Point&) { return f_F; };
  const FluidParams params = f;
  p.boundary_conditions = [params](const Mesh& mesh) {
    return box_boundary_conditions(mesh, params);
  };
  return p;
}

// The fluid step; a structure mesh it cannot fit (a user's structure.mesh whose
// Gamma_D is off x = 0 or whose other boundary is not one chain) is an input error.
BodyFittedFluid body_fitted_fluid(const Case& c, const Mesh& structure) {
  try {
    return BodyFittedFluid(body_fitted_params(c), structure, structure.label("Gamma_D"));
  } catch (const MeshError& e) {
    throw InputError(
        c.source + ": fluid.method = \"body-fitted\" cannot fit the fluid to this structure mesh" +
        (c.structure.mesh.empty() ? "" : " (structure.mesh = \"" + c.structure.mesh + "\")") +
        ": " + e.what() + "; allowed: \"penalised\"");
  }
}

// The fluid alone around the structure at rest: one body-fitted solve, its load.
CouplingResult solve_fluid_alone(StructureSetup& s, BodyFittedFluid& fluid, BodyFittedStep& last) {
  CouplingResult result;
  result.structure = s.solver->at_rest();
  try {
    last = fluid.solve(Eigen::VectorXd::Zero(2 * s.mesh().num_vertices()));
  } catch (const SolverFailure& e) {
    result.failure = std::string("the body-fitted fluid solve failed: ") + e.what();
    return result;
  }
  IterationRecord rec;
  rec.iteration = 1, rec.t_mesh = last.t_mesh, rec.t_fluid = last.t_fluid,
  rec.t_transfer = last.t_transfer;
  rec.fluid_triangles = last.mesh->num_triangles(), rec.remeshed = true;
  result.history.push_back(rec);
  result.iterations = 1;
  result.converged = true;
  result.fluid_load = last.load;
  return result;
}

Json fluid_json(const CouplingResult& result, const BodyFittedStep* last) {
  Json meshing = Json::array(), triangles = Json::array(), remeshed = Json::array();
  for (const auto& r : result.history)
    meshing.push_back(r.t_mesh), triangles.push_back(r.fluid_triangles),
        remeshed.push_back(r.remeshed);
  // Per pass: the time to make its mesh (Gmsh, or moving the last one), its
  // triangles, and whether Gmsh made it.
  Json j = {{"method", "body-fitted"},
            {"meshing_s", meshing},
            {"triangles", triangles},
            {"remeshed", remeshed}};
  if (last) j["unknowns"] = last->unknowns, j["gap"] = last->gap;
  return j;
}

std::string report(const Case& c, const CouplingResult& result, double max_u,
                   const MeshStatistics& f_stats, bool fluid_only) {
  char text[1024];
  if (fluid_only)
    std::snprintf(
        text, sizeof text,
        "%s: fluid alone around the structure at rest, body-fitted: %d triangles. Results in %s/.",
        c.name.c_str(), f_stats.triangles, c.output.dir.c_str());
  else
    std::snprintf(text, sizeof text,
                  "%s: %s after %d fixed-point iterations (body-fitted fluid, %s, last increment "
                  "%.4e, tol %g). "
                  "Max displacement %.4g m. Last fluid mesh %d triangles. Results in %s/.",
                  c.name.c_str(), result.converged ? "converged" : "NOT converged",
                  result.iterations, c.coupling.scheme.c_str(), result.final_increment,
                  c.coupling.tol, max_u, f_stats.triangles, c.output.dir.c_str());
  std::string r = text;
  if (!result.failure.empty()) r += " Failed: " + result.failure + ".";
  const std::string warning = convergence_warning(result, c.coupling.tol);
  if (!warning.empty()) r += " Warning: " + warning + ".";
  return r;
}

}  // namespace

RunResult run_body_fitted_case(const Case& c, const RunOptions& options) {
  PhaseTimes times;
  const Stopwatch total;
  SetupCache local_cache;
  SetupCache& cache = options.cache ? *options.cache : local_cache;
  const MeshStatistics s_stats = in_phase(times, "mesh", [&] { return statistics(cache.structure_mesh(c)); });
  StructureSetup& s = *in_phase(times, "structure", [&] { return &cache.structure(c); });
  BodyFittedFluid fluid = body_fitted_fluid(c, s.mesh());
  const bool fluid_only = c.coupling.max_iterations == 0;
  BodyFittedStep alone;
  CouplingResult result;
  const BodyFittedStep* last = nullptr;
  std::unique_ptr<Relaxation> relaxation;
  std::unique_ptr<BodyFittedCoupling> loop;
  if (fluid_only) {
    result = solve_fluid_alone(s, fluid, alone);
    last = alone.mesh ? &alone : nullptr;
  } else {
    relaxation = make_relaxation(c.coupling.scheme, {.omega0 = c.coupling.omega},
                                 assemble_vector_mass(s.mesh()));
    loop = std::make_unique<BodyFittedCoupling>(
        BodyFittedCoupling::Parts{*s.solver, s.b_applied, fluid, *relaxation}, c.coupling.tol,
        c.coupling.max_iterations);
    loop->progress = [&options](const std::string& line) {
      if (options.progress) options.progress(line);
    };
    if (options.initial_displacement) loop->initial = *options.initial_displacement;
    if (s.gap->normal()) {  // from rest, as run_fsi's couple: a cached setup's last run aside
      s.gap->relinearise(*s.solver, Eigen::VectorXd::Zero(2 * s.mesh().num_vertices()));
      loop->relinearise = [&s](const Eigen::VectorXd& u) { s.gap->relinearise(*s.solver, u); };
    }
    const ProbeSet probes(s.mesh(), c.output.probes);
    loop->observe = probes.observer();  // history.csv's u_x_i, u_y_i
    result = loop->run();
    last = loop->last_fluid();
  }
  for (const auto& r : result.history) {  // meshing each pass is part of the mesh phase
    times.add("mesh", r.t_mesh);
    times.add("fluid", r.t_fluid);
    times.add("structure", r.t_structure);
    times.add("transfer", r.t_transfer);
  }

  const Eigen::VectorXd& u = result.structure.u;
  const Mesh deformed = displaced(s.mesh(), component(u, 0), component(u, 1));
  if (result.failure.empty() && !std::isfinite(max_displacement(u)))
    result.failure = "the final displacement is not finite";
  if (!result.failure.empty()) result.converged = false;

  RunResult r;
  r.displacement = u;
  RunMeasures& m = r.measures = coupled_measures(c, result, fluid_only);
  m.structure_mesh = s_stats;
  m.fluid_mesh = last ? statistics(*last->mesh) : MeshStatistics{};  // the last pass's mesh
  if (!fluid_only) m.contact = summarize_contact(*s.solver, result.structure);
  Json& j = r.summary;
  j = summary_header(c);
  j["initial_state"] = options.initial_displacement ? "given" : "rest";
  j["mesh"] = {{"structure", to_json(m.structure_mesh)}, {"fluid", to_json(m.fluid_mesh)}};
  add_measures(j, m);
  j["tip_displacement"] = tip_displacement_json(c, s.mesh(), u);
  add_displacement_at(j, c, s.mesh(), u);
  j["structure_force"] = point_json(resultant(result.fluid_load));
  j["structure_load"] =
      point_json(resultant_off(result.fluid_load, s.mesh(), s.mesh().label("Gamma_D")));
  if (!fluid_only) {
    j["contact"] = to_json(*m.contact);
    if (s.gap->normal())
      add_gap_summary(j["contact"], c, s, result.structure);  // min_gap (SPEC §9)
    j["kkt"] = to_json(result.structure.qp.kkt);
    j["relaxation"] = {{"scheme", c.coupling.scheme},
                       {"omega0", c.coupling.omega},
                       {"projections", result.projections}};
  }
  // The fluid's force on each hole by the residual method (SPEC §10), on the last
  // pass's mesh and solution; κ empty: no penalty.
  if (c.obstacles_given)
    j["obstacles"] =
        hole_forces_json(c, last ? *last->mesh : s.mesh(), last ? &last->solution : nullptr, {});
  j["fluid"] = fluid_json(result, last);
  r.report = report(c, result, m.displacement->max, m.fluid_mesh, fluid_only);
  r.exit_status = exit_status_of(result);
  if (!result.failure.empty())
    r.failure = result.failure + " (the last good state is written in " + c.output.dir + "/)";

  auto files = [&](RunOutputs& out) {
    ScopedPhase phase(times, "output");
    if (c.output.vtu && last) {
      const Eigen::VectorXd chi = Eigen::VectorXd::Zero(last->mesh->num_triangles());
      const bool fluid_vtu = out.write("fluid.vtu", [&](const std::string& p) {
        write_fluid_vtu(p, c, *last->mesh, last->solution, chi);
      });
      if (!fluid_only) {
        const bool structure_vtu = out.write("structure.vtu", [&](const std::string& p) {
          write_structure_vtu(p, c, s, result.structure, true);
        });
        if (fluid_vtu && structure_vtu)
          out.write("fsi.pvd", [&](const std::string& p) {
            write_pvd(p, {{"fluid.vtu", 0}, {"structure.vtu", 1}});
          });
      }
    }
    if (c.output.png && last) {
      char note[256];
      std::snprintf(note, sizeof note, "body-fitted, omega = %g (%s), hF = %g, hS = %g;  %s",
                    c.coupling.omega, c.coupling.scheme.c_str(), c.fluid->h, c.structure.h,
                    fluid_only ? "structure at rest"
                               : (std::to_string(result.iterations) + " iterations" +
                                  (result.converged ? "" : " (not converged)"))
                                     .c_str());
      out.write(fluid_only ? "fluid.png" : "fsi.png", [&](const std::string& p) {
        write_fluid_png(p, c, *last->mesh, last->solution, deformed, {},
                        c.name + ": fluid velocity magnitude", note);
      });
      if (!fluid_only)
        out.write("structure.png",
                  [&](const std::string& p) { write_structure_png(p, c, s, result.structure); });
    }
    out.write("history.csv", [&](const std::string& p) { write_history(p, result.history, true); });
    out.write("case.toml", [&](const std::string& p) {
      write_atomically(p, [&](std::ostream& o) { o << to_toml(c); });
    });
  };
  write_outputs(c, r, files, [&](Json& summary) { finish_timing(summary, r.measures, times, total); });
  return r;
}

}  // namespace fsi
