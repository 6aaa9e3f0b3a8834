// The coupled problem and the fluid alone with fluid.method = "body-fitted": the
// fluid on a mesh of D \ φ(Ω_S0) made for each fixed-point pass, no penalty
// (coupling/body_fitted_fluid.hpp). summary.json carries the keys of the penalised
// run that mean the same here (max_displacement, tip_displacement, structure_force,
// contact, kkt, timing_s, obstacles[i].force with [[obstacles]], ...), fluid.method and
// the meshing time of each pass; no ‖v‖ in the structure (v = 0 on Γ_u by
// construction) and no ε.
#include <cmath>
#include <cstdio>
#include <optional>

#include "common/errors.hpp"
#include "common/fault.hpp"
#include "common/interrupt.hpp"
#include "coupling/body_fitted_step.hpp"
#include "coupling/fixed_point.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "mesh/mesh_error.hpp"
#include "run/outputs/field_arrays.hpp"
#include "run/outputs/coupling_outputs.hpp"
#include "run/outputs/fluid_outputs.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_setup.hpp"
#include "run/fluid_structure_problem.hpp"
#include "run/outputs/obstacle_forces.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/problem_kinds.hpp"
#include "fem/probes.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/outputs/structure_outputs.hpp"
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
  const MomentumModel model = momentum_model(f);
  p.form = model.form;
  p.rho = model.rho;
  p.newton = {f.rho, f.newton_tol, f.newton_max_steps};
  p.f = fluid_body_force(f);
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

Json fluid_json(const CouplingResult& result, const BodyFittedSolve* last) {
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

// What the two body-fitted kinds share: the structure's set-up, the fluid of the
// last pass (its mesh and fields), the summary and the files.
class BodyFittedProblem : public FluidStructureProblem {
 public:
  using FluidStructureProblem::FluidStructureProblem;

  void set_up(PhaseTimes& times) override {
    s_stats_ = in_phase(times, "mesh", [&] { return statistics(cache_.structure_mesh(c_)); });
    s_ = in_phase(times, "structure", [&] { return &cache_.structure(c_); });
    fluid_.emplace(body_fitted_fluid(c_, s_->mesh()));
  }

  void measure(RunResult& r) override {
    const Eigen::VectorXd& u = result_.structure.u;
    deformed_ = displaced(s_->mesh(), component(u, 0), component(u, 1));
    if (result_.failure.empty() && !std::isfinite(max_displacement(u)))
      result_.failure = "the final displacement is not finite";
    measure_final_state(r, last_ ? statistics(*last_->mesh) : MeshStatistics{});  // the last pass's mesh
  }

  void summarise(RunResult& r) override {
    const RunMeasures& m = r.measures;
    Json& j = r.summary;
    j = summary_header(c_, kind());
    j["initial_state"] = options_.initial_displacement ? "given" : "rest";
    j["mesh"] = {{"structure", to_json(m.structure_mesh)}, {"fluid", to_json(m.fluid_mesh)}};
    add_measures(j, m);
    add_structure_displacements(j, c_, *s_, result_);
    summarise_structure(j, m);
    // The fluid's force on each hole by the residual method (SPEC §10), on the last
    // pass's mesh and solution; κ empty: no penalty.
    if (c_.obstacles_given)
      j["obstacles"] = hole_forces_json(c_, last_ ? *last_->mesh : s_->mesh(), last_ ? &last_->solution : nullptr, {});
    if (!c_.output.fluid_probes.empty() && last_) j["fluid_at"] = fluid_probes_json(c_, *last_->mesh, &last_->solution);
    j["fluid"] = fluid_json(result_, last_);
    j["fluid"].update(flow_json(c_));
    r.report = report(m);
    if (!result_.failure.empty()) r.report += " Failed: " + result_.failure + ".";
    if (!m.convergence_warning.empty()) r.report += " Warning: " + m.convergence_warning + ".";
  }

  // The last pass's fluid on its own mesh (χ = 0: the structure is a hole in it).
  void final_fields(FinalFields& out) const override {
    if (s_) out.structure = structure_arrays_if_solved(*s_, result_.structure);
    if (last_)
      out.fluid = fluid_arrays(*last_->mesh, last_->solution, Eigen::VectorXd::Zero(last_->mesh->num_triangles()));
  }

  void write(RunOutputs& out) override {
    bool fluid_vtu = false;
    if (c_.output.vtu && last_) {
      const Eigen::VectorXd chi = Eigen::VectorXd::Zero(last_->mesh->num_triangles());
      fluid_vtu = out.write("fluid.vtu", [&](const std::string& p) {
        write_fluid_vtu(p, c_, *last_->mesh, last_->solution, chi);
      });
    }
    if (c_.output.png && last_) {
      char note[256];
      std::snprintf(note, sizeof note, "body-fitted, omega = %g (%s), hF = %g, hS = %g;  %s", c_.coupling.omega,
                    c_.coupling.scheme.c_str(), c_.fluid->h, c_.structure.h, picture_state().c_str());
      out.write(picture_name(), [&](const std::string& p) {
        write_fluid_png(p, c_, *last_->mesh, last_->solution, deformed_, {}, c_.name + ": fluid velocity magnitude",
                        note);
      });
    }
    write_structure(out, fluid_vtu);
    write_case_toml(out, c_);
  }

 protected:
  void add_pass_times(PhaseTimes& times) const {
    for (const auto& r : result_.history) {  // meshing each pass is part of the mesh phase
      times.add("mesh", r.t_mesh);
      times.add("fluid", r.t_fluid);
      times.add("structure", r.t_structure);
      times.add("transfer", r.t_transfer);
    }
  }

  std::optional<BodyFittedFluid> fluid_;
  const BodyFittedSolve* last_ = nullptr;  // the fluid solve that produced the result's load
};

// The fixed point of SPEC §5 with the fluid remeshed each pass
// (coupling/body_fitted_step.hpp).
class BodyFittedFsi final : public BodyFittedProblem {
 public:
  using BodyFittedProblem::BodyFittedProblem;

  void solve(PhaseTimes& times) override {
    const SparseMatrix M = assemble_vector_mass(s_->mesh());  // L²(Ω_S0): the stop's and the relaxation's
    auto relaxation = make_relaxation(c_.coupling.scheme, {.omega0 = c_.coupling.omega}, M);
    fluid_step_.emplace(*fluid_);
    StructureStep structure(*s_->solver, s_->gap.get());
    FixedPointCoupling loop(*fluid_step_, structure, s_->b_applied, *relaxation, M, c_.coupling.tol,
                            c_.coupling.max_iterations);
    loop.progress = [this](const std::string& line) {
      if (options_.progress) options_.progress(line);
    };
    if (options_.initial_displacement) loop.initial = *options_.initial_displacement;
    const ProbeSet probes(s_->mesh(), c_.output.probes);
    loop.observe = probe_observer(probes);  // history.csv's u_x_i, u_y_i
    result_ = loop.run();
    last_ = fluid_step_->last();
    add_pass_times(times);
  }

 private:
  void measure_structure(RunMeasures& m) override { measure_coupled_structure(m); }
  void summarise_structure(Json& j, const RunMeasures& m) override { summarise_coupled_structure(j, m); }
  void write_structure(RunOutputs& out, bool fluid_vtu_written) override {
    write_coupled_files(out, c_, *s_, result_, last_ != nullptr, fluid_vtu_written, true);
  }
  const char* picture_name() const override { return "fsi.png"; }
  std::string picture_state() const override { return passes_note(); }
  std::string report(const RunMeasures& m) const override {
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: %s after %d fixed-point iterations (body-fitted fluid, %s, last increment %.4e, tol %g). "
                  "Max displacement %.4g m. Last fluid mesh %d triangles. Results in %s/.",
                  c_.name.c_str(), result_.converged ? "converged" : "NOT converged", result_.iterations,
                  c_.coupling.scheme.c_str(), result_.final_increment, c_.coupling.tol, m.displacement->max,
                  m.fluid_mesh.triangles, c_.output.dir.c_str());
    return text;
  }

  std::optional<BodyFittedStep> fluid_step_;  // owns the last pass's fluid (last_)
};

// One body-fitted solve around the structure at rest, and its load.
class BodyFittedFluidAtRest final : public BodyFittedProblem {
 public:
  using BodyFittedProblem::BodyFittedProblem;
  const char* kind() const override { return "fluid"; }

  void solve(PhaseTimes& times) override {
    result_.structure = s_->solver->at_rest();
    try {
      alone_ = fluid_->solve(Eigen::VectorXd::Zero(2 * s_->mesh().num_vertices()));
    } catch (const SolverFailure& e) {
      result_.failure = std::string("the body-fitted fluid solve failed: ") + e.what();
      return;
    }
    IterationRecord rec;
    rec.iteration = 1, rec.t_mesh = alone_.t_mesh, rec.t_fluid = alone_.t_fluid, rec.t_transfer = alone_.t_transfer;
    rec.fluid_triangles = alone_.mesh->num_triangles(), rec.remeshed = true;
    result_.history.push_back(rec);
    result_.iterations = 1;
    result_.converged = true;
    result_.fluid_load = alone_.load;
    last_ = alone_.mesh ? &alone_ : nullptr;
    add_pass_times(times);
  }

 private:
  void measure_structure(RunMeasures&) override {}
  void summarise_structure(Json&, const RunMeasures&) override {}
  // history.csv: the one pass's mesh and timings.
  void write_structure(RunOutputs& out, bool) override {
    out.write("history.csv", [&](const std::string& p) { write_history(p, result_.history, true); });
  }
  const char* picture_name() const override { return "fluid.png"; }
  std::string picture_state() const override { return "structure at rest"; }
  std::string report(const RunMeasures& m) const override {
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: fluid alone around the structure at rest, body-fitted: %d triangles. Results in %s/.",
                  c_.name.c_str(), m.fluid_mesh.triangles, c_.output.dir.c_str());
    return text;
  }

  BodyFittedSolve alone_;
};

}  // namespace

std::unique_ptr<Problem> body_fitted_fsi(const Case& c, const RunOptions& options) {
  return std::make_unique<BodyFittedFsi>(c, options);
}

std::unique_ptr<Problem> body_fitted_fluid_at_rest(const Case& c, const RunOptions& options) {
  return std::make_unique<BodyFittedFluidAtRest>(c, options);
}

}  // namespace fsi
