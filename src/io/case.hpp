// A case: the validated parameters of one run (SPEC §8). Defaults are the paper's
// §7.2 values; a case file without a [fluid] section is the contact-only problem.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// fluid.Vmax, fluid.f and structure.f (each of f's components) are a number or an
// expression in x, y, t (SPEC §10; common/expression.hpp), compiled when the case is
// read (a bad one is an InputError naming the column). With an expression the number
// beside it (Vmax, f) holds, for the checks between keys and the estimates made from
// the case (the strain scale, the Reynolds number), a magnitude: its value of largest
// magnitude, sign kept, at 5 × 5 points of the fluid box (structure.f: of the rectangle
// L × H) at t = 0 (case_expressions.cpp). A constant expression ("8.0") is its value
// there, exactly. The solvers see neither: run/case_fields.hpp makes the fields.

struct StructureParams {
  // SPEC §9: "rectangle" (L × H, generated) | "mesh" (the .msh file `mesh`) | "geo"
  // (the Gmsh script `geo`, meshed at h). A mesh given without shape means "mesh".
  std::string shape = "rectangle";
  double L = 0.3, H = 0.03;
  bool extent_given = false;  // L or H set: a mesh's or script's extent must match
  double E = 3.0e5, nu = 0.45;
  Point f{0.0, -9.81 * 1100.0};  // f_S, N/m³ (see f_expression)
  // structure.f's components given as expressions in x, y, t (SPEC §10), "" where a
  // number (the note above StructureParams).
  std::array<std::string, 2> f_expression;
  Point h_N{0.0, 0.0};           // surface load on Γ_N, N/m²
  double h = 0.015;              // hS
  std::string mesh;              // optional .msh file (resolved path)
  std::string geo;               // the .geo script of shape "geo" (resolved path)
  // SPEC §11: "linear" (eq. 16, the paper) | "saint-venant-kirchhoff" | "neo-hookean".
  std::string model = "linear";
  std::string element = "P1";  // structure.element (SPEC §11): "P1" | "P2"
  // Who makes the rectangle's mesh: "lattice" (the project's generator) | "gmsh"
  // (Frontal-Delaunay: the meshes of fsicontact before issue 15).
  std::string mesher = "lattice";
  // SPEC §12 (with [time]): the density ρ_S (kg/m³; 0: not given), the uniform initial
  // velocity v0 (m/s; zero on Γ_D), whether Γ_D holds the structure (false: a free
  // body, its Γ_D edges free like Γ_N's; [time] only), and its mass matrix:
  // "consistent", or "redistributed" (no mass on the contact candidates, Khenous,
  // Laborde & Renard 2008; P1 only; solid/structure_mass.hpp).
  double rho = 0;
  Point v0{0.0, 0.0};
  bool clamped = true;
  std::string mass = "redistributed";
  bool rectangle() const { return shape == "rectangle"; }
  // The given file (mesh or script), for messages; empty for the rectangle.
  const std::string& file() const { return shape == "geo" ? geo : mesh; }
};

struct ObstacleParams {
  double x0 = 0.2, y0 = -0.07, r = 0.05;
  double gamma = 0.8;  // Γ_C = (x0 − γr, x0 + γr) × {0}
  double xc_min() const { return x0 - gamma * r; }
  double xc_max() const { return x0 + gamma * r; }
};

// One rigid obstacle of [[obstacles]] (SPEC §9).
struct ObstacleSpec {
  std::string shape;                       // "disk" | "polygon" | "half-plane"
  double x0 = 0, y0 = 0, r = 0;            // disk
  std::vector<Point> points;               // polygon: its corners, either orientation
  Point point = Point::Zero();             // half-plane: a point on its boundary
  Point normal = Point::Zero();            // and its outward normal (non-zero, as given)
};

// The box sides Σ1 … Σ4 by their keys fluid.left, bottom, right, top (SPEC §10 "Box
// sides"), in the order of FluidParams::sides.
inline constexpr std::array<const char*, 4> kBoxSideKeys = {"left", "bottom", "right", "top"};

struct FluidParams {
  double L1 = 0.41, H1 = 0.5, H2 = 0.5;
  // Σ1 left (x = 0), Σ2 bottom (y = −H2), Σ3 right (x = L1), Σ4 top (y = H1): each
  // "wall" (v = 0), "inflow" (parabolic, into the box, peak Vmax) or "outflow"
  // (traction-free). The defaults are the paper's (§3).
  std::array<std::string, 4> sides = {"wall", "outflow", "wall", "inflow"};
  double mu = 0.0035;
  Point f{0.0, -9.81 * 100.0};  // f_F, N/m³ (see f_expression)
  double Vmax = 8.0;             // the inflow's peak (see Vmax_expression)
  // fluid.f's components and fluid.Vmax given as expressions in x, y, t (SPEC §10), ""
  // where a number (the note above StructureParams).
  std::array<std::string, 2> f_expression;
  std::string Vmax_expression;
  double h = 0.01;                  // hF
  std::string mesh;                 // optional .msh file (resolved path)
  std::string mesher =
      "lattice";  // who makes the box's mesh: "lattice" | "gmsh" (as structure.mesher)
  std::string chi = "barycentre";   // "barycentre" | "area-fraction"
  // "schur": the far field factorised once per run, only the region around the
  // structure per χ; "whole": all of K per χ (PenalisedStokes, FluidFactorization).
  std::string factorization = "schur";
  // SPEC §13: "mumps" (sequential MUMPS, called directly), "petsc-mumps" (MUMPS
  // through PETSc) or "petsc-iterative" (GMRES with a Schur-complement field split:
  // fluid/petsc_plugin.cpp) to the relative residual linear_tol in at most
  // linear_max_iterations iterations. Both PETSc solvers take the whole factorisation.
  std::string linear_solver = "mumps";
  double linear_tol = 1e-10;
  int linear_max_iterations = 1000;
  // "petsc-iterative"'s Krylov method: "gmres" (restart 100, the default) or
  // "bicgstab" (a fixed memory of 7 vectors: for the largest meshes).
  std::string krylov = "gmres";
  // With "schur": far fields whose factorisation takes more memory than this (MB,
  // MUMPS's figure) are not kept between expansions, each expansion refactorises
  // them (one more far-field factorisation per run for about half the peak memory).
  double keep_far_factors_mb = 128;
  // Refinement where the structure goes: triangles of size h_near inside a band of
  // width `band` around the structure at rest and at its load-alone contact solution
  // (or inside band_box, [x_min, y_min, x_max, y_max], if given), hF elsewhere, through
  // a Gmsh size field. 0: no band, hF everywhere (the paper's meshes).
  double h_near = 0;
  double band = 0.02;
  // Refinement at the obstacles (the box's holes): triangles of size h_obstacles on
  // their boundaries, growing by kBandGrowth per unit of distance up to the band's
  // or hF (a Gmsh size field; fluid.mesher = "gmsh"). Where the forces on them are
  // computed (the DFG benchmarks) the mesh is needed there. 0: none.
  double h_obstacles = 0;
  std::optional<std::array<double, 4>> band_box;
  // "penalised": the fictitious domain of §3 (the paper); "body-fitted": D minus the
  // deformed structure, remeshed each fixed-point pass, no-slip on the structure and
  // its traction as the load: an independent check for configurations without contact.
  std::string method = "penalised";
  // SPEC §10: "stokes" (the paper's creeping flow) or "navier-stokes", adding ρ(v·∇)v
  // with the density rho (kg/m³; required then), solved by Newton's method to the
  // relative residual newton_tol in at most newton_max_steps steps. The viscous term
  // in the symmetric form 2μ ε:ε or the gradient form μ∇:∇ (the DFG benchmarks').
  std::string model = "stokes";
  double rho = 0;  // 0: not given
  double newton_tol = 1e-10;
  int newton_max_steps = 30;
  std::string viscous_form = "symmetric";
  // The fluid's element: "mini" (P1 + bubble / P1, §4, the paper's) or "taylor-hood"
  // (P2 / P1, isoparametric on the disks' holes: second order in H¹; the fluid alone,
  // structure.shape = "none", so far).
  std::string element = "mini";
  bool taylor_hood() const { return element == "taylor-hood"; }
  bool navier_stokes() const { return model == "navier-stokes"; }
  double size_near() const { return h_near > 0 ? h_near : h; }  // the size at the structure
};

struct CouplingParams {
  double eps = 1.0e-5;
  double omega = 0.1;
  double tol = 1.0e-4;
  int max_iterations = 100;
  std::string scheme = "constant";  // "constant" | "aitken" | "iqn-ils"
  // SPEC §12: IQN-ILS keeps the secant pairs of this many past time steps (windows).
  int reuse = 0;
  // How ε follows the mesh: "fixed" (the case's ε on every level of a refinement
  // study) or "h^p" (ε · (h/h₀)^p, h the fluid size at the structure, h₀ the case's
  // own; a single run uses ε as given), or "layer": ε = (c h)²/μ_F with c =
  // kLayerFraction, so that the Brinkman layer sqrt(μ_F ε) is c times the fluid size
  // at the structure, in a single run too (docs/validation.md, "The penalty's error").
  std::string eps_rule = "fixed";
  static constexpr double kLayerFraction = 0.5;
  bool eps_given = false, eps_rule_given = false;  // stated in the file or by --set
  // SPEC §11: "small" (eq. 33) | "large" (the exact pull-back with J and F⁻ᵀ).
  std::string force = "small";
  // The fluid sampled on the structure's triangles cut into m² each (1: at its
  // vertices, the paper's eq. 33); P1 structures, penalised fluid (issue 27). With
  // eps_rule = "layer" and no stated value: layer_sampling (the layer resolved).
  int force_sampling = 1;
  bool force_sampling_given = false;
  double eps_power() const;  // p of "h^p"; 2 for "layer"; 0 for "fixed"
};

struct ContactParams {
  std::string solver = "active-set";  // "active-set" | "ipopt"
  // SPEC §9: "paper" (eq. 15, ψ linearised at the reference configuration) | "normal"
  // (the signed distance, re-linearised about the current state).
  std::string gap = "paper";
  std::string boundary = "Gamma_C";  // the candidate edges: "Gamma_C" | "all" (every edge off Γ_D)
};

struct OutputParams {
  std::string dir;   // default out/<name>
  std::string dir_origin;  // where dir came from (the file, --set, --out), for messages
  bool png = true;
  bool vtu = true;
  std::string vtu_format = "binary";  // "binary" (appended raw) | "zlib" | "ascii" (io/vtu.hpp)
  // output.probes (SPEC §11): material points, in reference coordinates, where
  // summary.json (displacement_at) and history.csv report the displacement.
  std::vector<Point> probes;
  // output.fluid_probes (SPEC §10): points of D (the current configuration: the fixed
  // mesh) where summary.json's fluid_at reports v and p, e.g. the DFG benchmark's
  // pressure difference.
  std::vector<Point> fluid_probes;
};

// [time] (SPEC §12): the case is time-dependent. So far for the fluid alone
// (structure.shape = "none"); the structure's dynamics, contact in time and the
// coupled time loop are issue 30's next parts.
struct TimeParams {
  double dt = 0;                // time.dt (s), required
  double t_end = 0;             // time.t_end (s), required; the run takes round(t_end/dt) steps
  std::string scheme = "bdf1";  // time.scheme: "bdf1" | "bdf2" (the fluid's)
  int output_every = 1;         // time.output_every: steps between written frames
  // time.checkpoint_every: steps between checkpoints (checkpoint.bin, --resume); 0: one
  // at the run's end only (also when it is stopped or fails: the last good state).
  int checkpoint_every = 0;
  // time.start_from: "rest" (u = 0, u̇ = structure.v0, v = 0) | "steady" (the steady
  // solution of the same case with its data at t = 0, u̇ = structure.v0, ü = 0).
  std::string start_from = "rest";
  // time.convection (Navier–Stokes): "implicit" (Newton's method in every step, to
  // fluid.newton_tol) | "semi-implicit" (one Oseen solve a step, the convecting velocity
  // extrapolated from the last steps: 2vⁿ − vⁿ⁻¹ with BDF2, vⁿ with BDF1).
  std::string convection = "implicit";
  int steps() const { return static_cast<int>(std::llround(t_end / dt)); }
};

struct Case {
  std::string name = "paper-7.2";
  std::string source = "(built-in paper-7.2 case)";  // where it came from, for messages
  StructureParams structure;
  ObstacleParams obstacle;
  bool obstacle_given = false;          // the file or --set has an [obstacle] table
  std::vector<ObstacleSpec> obstacles;  // [[obstacles]]
  bool obstacles_given = false;         // [[obstacles]] present (possibly empty: no obstacle)
  std::optional<FluidParams> fluid = FluidParams{};
  CouplingParams coupling;
  ContactParams contact;
  OutputParams output;
  std::optional<TimeParams> time;  // [time]: nullopt for a steady case
};

// Loads `path` (or the built-in §7.2 case if empty), applies `overrides`
// ("section.key=value", value in TOML syntax or a bare string), then `out_dir` as
// output.dir (taken verbatim, never parsed: --out), and validates every key and the
// checks between keys. The file system is not looked at beyond the case file: see
// check_output_dir (io/output_path.hpp) and the mesh checks (run/).
// Throws InputError "<file>: <key> ...; allowed: ..." on the first problem.
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {},
               const std::string& out_dir = "");

// The same from TOML text; `origin` names it in messages, relative mesh paths
// resolve against the current directory.
Case load_case_text(const std::string& text, const std::string& origin,
                    const std::vector<std::string>& overrides = {}, const std::string& out_dir = "");

// Where a study's cases come from (sweep's rows, converge's levels, each loaded with its
// own overrides): a case file's path (empty: the built-in §7.2 case), implicitly, or
// TOML text (the Python module's dict) named by `origin`.
struct CaseSource {
  CaseSource(std::string case_path = "") : path(std::move(case_path)) {}  // NOLINT: a path is a source
  static CaseSource text_named(std::string toml_text, std::string origin);
  // The file, or the text's origin: what messages and summaries name.
  const std::string& name() const { return path; }
  Case load(const std::vector<std::string>& overrides = {}, const std::string& out_dir = "") const;

  std::string path;                 // the file, or the text's origin
  std::optional<std::string> text;  // TOML text instead of a file
};

// The p of coupling.eps_rule "h^p" (0 for "fixed", 2 for "layer"); none if the rule is not known.
std::optional<double> eps_rule_power(const std::string& rule);

// ε of eps_rule = "layer" for a fluid of viscosity mu and size `h` at the structure.
double layer_eps(double mu, double h);
// eps_rule = "layer"'s default coupling.force_sampling: the structure's triangles
// (size h_S) cut into sub-triangles no wider than the layer, m = ⌈h_S / layer⌉ in [1, 8].
int layer_sampling(double h_S, double layer);

// The loads' strain scale against the small strains of linear elasticity, for a
// structure of diameter `diam`: the problem in words ("structure.E = ... is too soft
// ...; allowed: ...") or "" (checked by load_case for the rectangle, by the mesh checks
// for a structure from a file, whose diameter is known once it is read).
std::string load_strain_problem(const Case& c, double diam);

// Every key a case may set ("name", "structure.L", ...), in the order they are read.
std::vector<std::string> case_keys();

// The resolved case as TOML text (written beside the results, rerunnable).
std::string to_toml(const Case& c);

// Limits on problem size (stated in error messages and docs/reliability.md).
struct CaseLimits {
  double structure_triangles = 2.0e5;  // the active-set solver's dense m × m contact Schur complement
  double fluid_triangles = 4.0e6;      // memory of the factorisation
  // fluid.linear_solver = "petsc-iterative": 1.2 kB a triangle for a solve, 1.4 kB over
  // several passes, 24 GB at this limit on one rank (docs/performance.md, "K freed
  // before the set-up").
  double fluid_triangles_iterative = 2.0e7;
  int max_iterations = 100000;
  double time_steps = 1.0e6;  // time.t_end / time.dt
  double time_frames = 1.0e5;  // written frames: time.t_end / time.dt / time.output_every + 1
};
// The limits in force: the defaults above; the command-line fuzzer lowers them so
// that each of its inputs runs in milliseconds (fuzz/fuzz_cli.cpp).
CaseLimits& case_limits();
// The fluid triangles a case may have with its linear solver.
double fluid_triangle_limit(const FluidParams& f);

}  // namespace fsi
