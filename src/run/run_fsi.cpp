// The coupled problem (SPEC §5) and, with coupling.max_iterations = 0, the fluid
// alone around the undeformed structure (SPEC §3).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "coupling/fixed_point.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "run/fluid_outputs.hpp"
#include "run/fluid_setup.hpp"
#include "run/output_dir.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/structure_outputs.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

std::string path_in(const Case& c, const char* name) {
  return (std::filesystem::path(c.output.dir) / name).string();
}

void write_history(const std::string& path, const std::vector<IterationRecord>& history) {
  write_atomically(path, [&](std::ostream& out) {
    out << "iteration,increment_l2,omega,active_nodes,chi_triangles,fluid_reused,t_chi_s,t_fluid_s,"
           "t_transfer_s,t_structure_s\n"
        << std::setprecision(10);
    for (const auto& r : history)
      out << r.iteration << ',' << r.increment << ',' << r.omega << ',' << r.active_nodes << ','
          << r.chi_triangles << ',' << (r.fluid_reused ? 1 : 0) << ',' << r.t_chi << ',' << r.t_fluid
          << ',' << r.t_transfer << ',' << r.t_structure << '\n';
  });
}

Json fluid_json(const PenalisedStokes& stokes) {
  const FluidTiming& t = stokes.timing();
  Json j = {{"unknowns", stokes.unknowns()},
          {"nonzeros", stokes.nonzeros()},
          {"solver", stokes.solver_name()},
          {"analyses", t.analyses},  // symbolic analyses: 1 per run, 0 for a sweep row reusing it
          {"factorizations", t.factorizations},
          {"reused_solutions", t.reused},
          {"assembly_s", t.assembly},
          {"analysis_s", t.analysis},  // included in factorization_s
          {"factorization_s", t.factorization},
          {"solve_s", t.solve}};
  j["factorization"] = stokes.factorization() == FluidFactorization::schur ? "schur" : "whole";
  // The substructured solve: far-field factorisations (one per near region; their
  // time is part of factorization_s), the expansions (part of solve_s), the last
  // region's size.
  j["far_field_factorizations"] = t.regions;
  j["far_factorization_s"] = t.far_factorization;
  j["expansion_s"] = t.expansion;
  // Far fields over fluid.keep_far_factors_mb are refactorised for each expansion.
  j["far_factor_mb"] = stokes.region() ? stokes.region()->far_factor_mb() : 0.0;  // the region in use
  j["far_field_refactorizations"] = t.far_refactorizations;
  if (const RegionSchurSolver* r = stokes.region()) {
    j["near_unknowns"] = r->near_unknowns();
    j["interface_unknowns"] = r->interface_unknowns();
  }
  return j;
}

// ‖v_h‖ over the fluid triangles where χ = 1 (the region the penalty acts on).
double velocity_l2_on_chi(const FluidField& field, const Mesh& fluid_mesh, const Eigen::VectorXd& chi) {
  Mesh region;
  region.vertices = fluid_mesh.vertices;
  for (int t = 0; t < fluid_mesh.num_triangles(); ++t)
    if (chi[t] >= 1.0) region.triangles.push_back(fluid_mesh.triangles[t]);
  return velocity_l2_over(field, region);
}

}  // namespace

RunResult run_fsi_case(const Case& c, const RunOptions& options) {
  PhaseTimes times;
  const Stopwatch total;
  auto progress = [&](const std::string& prefix) {
    return [&options, prefix](const std::string& line) {
      if (options.progress) options.progress(prefix + line);
    };
  };
  SetupCache local_cache;
  SetupCache& cache = options.cache ? *options.cache : local_cache;
  MeshStatistics s_stats, f_stats;
  {
    ScopedPhase phase(times, "mesh");
    s_stats = statistics(cache.structure_mesh(c));
    f_stats = statistics(cache.fluid_mesh(c));
  }
  prepare_output_dir(c.output.dir, c.source);

  StructureSetup* s_ptr = nullptr;
  {
    ScopedPhase phase(times, "structure");
    s_ptr = &cache.structure(c);  // no QP progress lines: one per iteration would swamp stderr
  }
  FluidSetup* f_ptr = nullptr;
  {
    ScopedPhase phase(times, "fluid");
    f_ptr = &cache.fluid(c);
  }
  StructureSetup& s = *s_ptr;
  FluidSetup& f = *f_ptr;
  const Mesh& ref = s.mesh();
  const bool fluid_only = c.coupling.max_iterations == 0;

  CouplingResult result;
  if (fluid_only) {
    const Stopwatch clock;
    f.stokes->set_chi((*f.chi)(ref));
    try {
      f.stokes->solve();
    } catch (const std::exception& e) {
      throw SolverFailure(std::string("the fluid solve failed: ") + e.what());
    }
    times.add("fluid", clock.elapsed());
    result.structure = s.solver->at_rest();
    result.converged = true;
  } else {
    const FluidParams& fp = *c.fluid;
    const Point f_F = fp.f;
    const FluidForce force(ref, fp.mu, c.coupling.eps, [f_F](const Point&) { return f_F; });
    auto relaxation = make_relaxation(c.coupling.scheme, {.omega0 = c.coupling.omega},
                                      assemble_vector_mass(ref));
    FixedPointCoupling loop({*s.solver, s.b_applied, *f.stokes, *f.locator, *f.chi, force, *relaxation},
                            c.coupling.tol, c.coupling.max_iterations);
    loop.progress = progress("");
    loop.complete_at_end = c.output.png || c.output.vtu;
    result = loop.run();
    for (const auto& r : result.history) {
      times.add("fluid", r.t_fluid);
      times.add("structure", r.t_structure);
      times.add("transfer", r.t_chi + r.t_transfer);
      times.add("chi", r.t_chi);
    }
  }

  // The final state: ũ (the solution if converged; after a failure the last good
  // one) and the last successful fluid solution.
  const Eigen::VectorXd& u = result.structure.u;
  const Eigen::VectorXd u1 = component(u, 0), u2 = component(u, 1);
  const Mesh deformed = displaced(ref, u1, u2);
  const FluidSolution& fluid = f.stokes->last_solution();
  const Eigen::VectorXd& chi = f.stokes->last_solution_chi();
  // The norms read the fields in the structure only, which a near-only solution (no
  // drawn or written fluid, or a failed expansion) holds; if the structure reaches
  // beyond it, the solution is completed first, and failing that they are NaN.
  double v_norm = NAN, v_norm_chi = NAN;
  if (f.stokes->has_solution()) {
    auto norms = [&] {
      const FluidField field(*f.locator, fluid);
      v_norm = velocity_l2_over(field, deformed);
      v_norm_chi = velocity_l2_on_chi(field, *f.mesh, chi);
    };
    try {
      norms();
    } catch (const FieldNotComputed&) {
      try {
        f.stokes->complete();
        norms();
      } catch (const std::exception&) {
        v_norm = v_norm_chi = NAN;
      }
    }
  }
  const bool has_fluid = f.stokes->has_solution() && fluid.exact_on == nullptr;  // everywhere
  const std::vector<int> contact_vertices =
      fluid_only ? std::vector<int>{} : active_vertices(*s.solver, result.structure);

  {
    ScopedPhase phase(times, "output");
    if (c.output.vtu && has_fluid) {
      write_fluid_vtu(path_in(c, "fluid.vtu"), *f.mesh, fluid, chi);
      if (!fluid_only) {
        write_structure_vtu(path_in(c, "structure.vtu"), s, result.structure, true);
        write_pvd(path_in(c, "fsi.pvd"), {{"fluid.vtu", 0}, {"structure.vtu", 1}});
      }
    }
    char note[256];
    std::snprintf(note, sizeof note, "eps = %g, omega = %g (%s), hF = %g, hS = %g;  %s", c.coupling.eps,
                  c.coupling.omega, c.coupling.scheme.c_str(), c.fluid->h, c.structure.h,
                  fluid_only ? "structure at rest"
                             : (std::to_string(result.iterations) + " iterations" +
                                (result.converged ? "" : " (not converged)")).c_str());
    if (c.output.png && has_fluid) {
      write_fluid_png(path_in(c, fluid_only ? "fluid.png" : "fsi.png"), c, *f.mesh, fluid, deformed,
                      contact_vertices, c.name + ": fluid velocity magnitude", note);
      if (!fluid_only) write_structure_png(path_in(c, "structure.png"), c, s, result.structure);
    }
    if (!fluid_only) write_history(path_in(c, "history.csv"), result.history);
    write_atomically(path_in(c, "case.toml"), [&](std::ostream& o) { o << to_toml(c); });
  }

  RunResult r;
  Json& j = r.summary;
  j["name"] = c.name;
  j["problem"] = fluid_only ? "fluid" : "fsi";
  j["parameters"] = to_json(c);
  j["mesh"] = {{"structure", to_json(s_stats)}, {"fluid", to_json(f_stats)}};
  j["converged"] = result.converged;
  j["status"] = !result.failure.empty() ? "failed"
                : result.interrupted    ? "interrupted"
                : result.converged      ? "converged"
                                        : "iteration limit";
  if (!result.failure.empty()) j["failure"] = result.failure;
  const std::string warning = convergence_warning(result, c.coupling.tol);
  if (!warning.empty()) j["convergence_warning"] = warning;
  j["iterations"] = result.iterations;
  if (!fluid_only) {
    j["paper_k"] = result.iterations - 1;  // the paper's counter k at the stop (§6)
    j["final_increment_l2"] = result.final_increment;
  }
  j["fluid_velocity_l2_in_structure"] = v_norm;
  j["fluid_velocity_l2_in_structure_over_eps"] = v_norm / c.coupling.eps;
  j["fluid_velocity_l2_on_chi"] = v_norm_chi;
  j["max_displacement"] = (u1.array().square() + u2.array().square()).sqrt().maxCoeff();
  j["min_displacement_y"] = u2.minCoeff();
  if (!fluid_only) {
    j["contact"] = to_json(summarize_contact(*s.solver, result.structure));
    j["kkt"] = to_json(result.structure.qp.kkt);
    j["relaxation"] = {{"scheme", c.coupling.scheme},
                       {"omega0", c.coupling.omega},
                       {"projections", result.projections}};
  }
  j["fluid"] = fluid_json(*f.stokes);
  j["timing_s"] = timing_json(times, total.elapsed());
  write_json(path_in(c, "summary.json"), j);

  char text[1024];
  if (fluid_only) {
    std::snprintf(text, sizeof text,
                  "%s: fluid alone around the structure at rest: %d unknowns on %d triangles, "
                  "solved in %.3f s (%s). |v| in the structure %.4e (eps %g, |v|/eps %.4g). "
                  "Results in %s/ (summary.json%s%s).",
                  c.name.c_str(), f.stokes->unknowns(), f_stats.triangles,
                  f.stokes->timing().factorization + f.stokes->timing().solve + f.stokes->timing().assembly,
                  f.stokes->solver_name().c_str(), v_norm, c.coupling.eps, v_norm / c.coupling.eps,
                  c.output.dir.c_str(), c.output.vtu ? ", fluid.vtu" : "", c.output.png ? ", fluid.png" : "");
  } else {
    const ContactSummary cs = summarize_contact(*s.solver, result.structure);
    std::snprintf(text, sizeof text,
                  "%s: %s after %d fixed-point iterations (%s, last increment %.4e, tol %g). "
                  "|v| in the structure %.5g, |v|/eps %.6g. Max displacement %.4g m; contact on %d "
                  "node(s)%s. Fluid %d triangles, structure %d. Results in %s/.",
                  c.name.c_str(), result.converged ? "converged" : "NOT converged", result.iterations,
                  c.coupling.scheme.c_str(), result.final_increment, c.coupling.tol, v_norm,
                  v_norm / c.coupling.eps, j["max_displacement"].get<double>(), cs.active_nodes,
                  cs.active_nodes ? (", X1 in [" + std::to_string(cs.x_min) + ", " + std::to_string(cs.x_max) + "] m").c_str() : "",
                  f_stats.triangles, s_stats.triangles, c.output.dir.c_str());
  }
  r.report = text;
  if (!warning.empty()) r.report += " Warning: " + warning + ".";
  if (!result.failure.empty())
    throw SolverFailure(result.failure + " (the last good state is written in " + c.output.dir + "/)");
  r.exit_status = result.interrupted ? kInterruptedExitStatus : result.converged ? 0 : 3;
  return r;
}

}  // namespace fsi
