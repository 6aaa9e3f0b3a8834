// Invalid input, end to end through the command line: one line on stderr naming
// the file, the key and what is allowed; exit status 2; nothing written.
#include <gtest/gtest.h>

#include <set>

#include "support/cli.hpp"
#include "support/msh.hpp"

namespace fsi::bad_input_test {
namespace {

namespace fs = std::filesystem;

// A valid contact-only case (§7.1, Fig. 5), to be spoiled one key at a time.
const std::string kValid = R"(name = "t"
[structure]
L = 0.06
H = 0.005
E = 3.0e5
nu = 0.3
f = [0.0, -1.0e4]
h = 0.0014
[obstacle]
x0 = 0.055
y0 = -0.012
r = 0.005
gamma = 0.8
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos) throw std::logic_error("test case: '" + from + "' not in case");
  return text.replace(pos, from.size(), to);
}

struct BadInput {
  std::string label;
  std::string case_text;  // written to case.toml
  std::string extra_args;
  std::vector<std::string> expected;  // substrings of the message
  std::vector<std::pair<std::string, std::string>> files = {};  // more files: name, text
};

std::string defect(const std::string& name) {
  return testing::slurp(std::string(FSICONTACT_SOURCE_DIR) + "/tests/data/fuzz-msh/" + name + ".msh");
}

std::string shipped(const std::string& name) {
  return testing::slurp(std::string(FSICONTACT_SOURCE_DIR) + "/cases/meshes/" + name);
}

// A beam of two blocks that share no vertex: the right one is held by nothing.
// Nodes: the left block's bottom 1–5 (Gamma_C on 2–3–4, above the obstacle at
// x0 = 0.015), its top 6, 7; the right block 8–11.
std::string floating_block_msh() {
  testing::HandMesh m;
  m.nodes = {{0, 0}, {0.012, 0}, {0.015, 0}, {0.018, 0}, {0.03, 0}, {0, 0.005}, {0.03, 0.005},
             {0.032, 0}, {0.06, 0}, {0.06, 0.005}, {0.032, 0.005}};
  m.triangles = {{1, 2, 6}, {2, 3, 6}, {3, 4, 6}, {4, 5, 6}, {5, 7, 6}, {8, 9, 10}, {8, 10, 11}};
  m.lines = {{"Gamma_D", {{6, 1}}},
             {"Gamma_C", {{2, 3}, {3, 4}}},
             {"Gamma_N", {{1, 2}, {4, 5}, {5, 7}, {7, 6}, {8, 9}, {9, 10}, {10, 11}, {11, 8}}}};
  return testing::msh22(m);
}

// A structure from a .geo script (SPEC §9) resting on a floor, and its script.
const std::string kGeo = R"(name = "t"
[structure]
geo = "s.geo"
E = 3.0e5
nu = 0.3
f = [0.0, -1.0e4]
h = 0.01
[contact]
gap = "normal"
boundary = "all"
[[obstacles]]
shape = "half-plane"
point = [0.0, -0.001]
normal = [0.0, 1.0]
)";
const std::string kBar = R"(Point(1) = {0, 0, 0}; Point(2) = {0.1, 0, 0}; Point(3) = {0.1, 0.02, 0}; Point(4) = {0, 0.02, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1}; Physical Curve("Gamma_D") = {4}; Physical Curve("Gamma_N") = {1, 2, 3};
)";

// The §7.2 case on the shipped fluid mesh (hF = 0.02), copied as box.msh.
const std::string kBoxCase = "[structure]\nh = 0.03\n[fluid]\nmesh = \"box.msh\"\n";

// The contact case with a fluid and [[obstacles]] instead of [obstacle], to be given
// its obstacles (kDisk: one valid disk below the beam).
const std::string kFsiObstacles =
    replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") +
    "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[fluid]\nh = 0.004\n";
const std::string kDisk = "[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.005\n";
// One [[obstacles]] polygon with these corners ("[x, y], [x, y], ...").
std::string polygon_obstacle(const std::string& corners) {
  return "[[obstacles]]\nshape = \"polygon\"\npoints = [" + corners + "]\n";
}

// n points of the kValid beam, "[x, y], [x, y], ...".
std::string many_probes(int n) {
  std::string list;
  for (int i = 0; i < n; ++i) list += (i ? ", " : "") + std::string("[0.01, 0.002]");
  return list;
}

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.label; }

// The table in four parts: one initializer list of 165 entries took g++ 16 s to compile
// (its exception clean-ups), a quarter of the whole suite's batch; in parts, a few seconds.
// Keys one at a time: unknown, of the wrong type, out of range; files that are not there.
std::vector<BadInput> bad_keys() {
  const std::string fsi = kValid + "[fluid]\n";
  return {
      {"unknown_key", replace(kValid, "E = 3.0e5", "E = 3.0e5\nYoung = 1"), "", {"case.toml", "structure.Young", "not a known key"}},
      {"unknown_section", kValid + "[solid]\nE = 1\n", "", {"case.toml", "solid", "allowed"}},
      {"wrong_type", replace(kValid, "E = 3.0e5", "E = \"stiff\""), "", {"structure.E", "must be a number"}},
      {"E_zero", replace(kValid, "E = 3.0e5", "E = 0"), "", {"structure.E", "out of range", "[1e-30, 1e+30]"}},
      {"E_negative", replace(kValid, "E = 3.0e5", "E = -3e5"), "", {"structure.E", "[1e-30, 1e+30]"}},
      {"E_nan", replace(kValid, "E = 3.0e5", "E = nan"), "", {"structure.E", "finite"}},
      {"E_inf", replace(kValid, "E = 3.0e5", "E = inf"), "", {"structure.E", "finite"}},
      {"nu_half", replace(kValid, "nu = 0.3", "nu = 0.5"), "", {"structure.nu", "[0, 0.499999995]"}},
      {"nu_negative", replace(kValid, "nu = 0.3", "nu = -0.1"), "", {"structure.nu", "[0, 0.499999995]"}},
      {"nu_singular_in_double_precision", replace(kValid, "nu = 0.3", "nu = 0.49999999999999"), "", {"structure.nu", "[0, 0.499999995]"}},
      {"h_zero", replace(kValid, "h = 0.0014", "h = 0"), "", {"structure.h", "out of range"}},
      {"h_negative", replace(kValid, "h = 0.0014", "h = -0.001"), "", {"structure.h"}},
      {"h_too_small", replace(kValid, "h = 0.0014", "h = 1e-6"), "", {"structure.h", "triangles", "limit"}},
      {"h_too_small_for_p2", replace(kValid, "h = 0.0014", "h = 8e-5"), "--set structure.element=P2", {"structure.h", "limit", "P2"}},
      {"gamma_one", replace(kValid, "gamma = 0.8", "gamma = 1.0"), "", {"obstacle.gamma", "(0, 1)"}},
      {"gamma_zero", replace(kValid, "gamma = 0.8", "gamma = 0"), "", {"obstacle.gamma", "(0, 1)"}},
      {"r_negative", replace(kValid, "r = 0.005", "r = -0.005"), "", {"obstacle.r", "[1e-30, 1e+30]"}},
      {"gamma_c_outside", replace(kValid, "x0 = 0.055", "x0 = 0.058"), "", {"obstacle.x0", "Gamma_C", "allowed"}},
      {"inside_obstacle", replace(kValid, "y0 = -0.012", "y0 = -0.002"), "", {"obstacle.y0", "inside the obstacle"}},
      {"f_not_vector", replace(kValid, "f = [0.0, -1.0e4]", "f = -1.0e4"), "", {"structure.f", "two numbers"}},
      {"f_three", replace(kValid, "f = [0.0, -1.0e4]", "f = [0, 1, 2]"), "", {"structure.f", "two numbers"}},
      {"malformed_toml", replace(kValid, "E = 3.0e5", "E = = 3"), "", {"case.toml:"}},
      {"bad_name", replace(kValid, "name = \"t\"", "name = \"../evil\""), "", {"name", "output directory"}},
      {"section_not_table", "fluid = 3\n" + kValid, "", {"case.toml: fluid", "table"}},
      {"omega_zero", fsi, "--set coupling.omega=0", {"--set coupling.omega", "(0, 1]"}},
      {"omega_large", fsi, "--set coupling.omega=1.5", {"coupling.omega", "(0, 1]"}},
      {"tol_zero", fsi, "--set coupling.tol=0", {"coupling.tol", "[1e-30, 1e+30]"}},
      {"far_budget_negative", fsi + "keep_far_factors_mb = -1\n", "", {"fluid.keep_far_factors_mb", ">= 0"}},
      {"eps_negative", fsi, "--set coupling.eps=-1e-5", {"coupling.eps", "[1e-12, 1e+30]"}},
      {"eps_underflow", fsi, "--set coupling.eps=1e-300", {"coupling.eps", "[1e-12, 1e+30]"}},
      {"scheme_unknown", fsi, "--set coupling.scheme=newton", {"coupling.scheme", "constant", "aitken", "iqn-ils"}},
      {"model_unknown", fsi, "--set structure.model=rubber", {"structure.model", "linear", "saint-venant-kirchhoff", "neo-hookean"}},
      {"force_unknown", fsi, "--set coupling.force=huge", {"coupling.force", "small", "large"}},
      {"element_unknown", fsi, "--set structure.element=P3", {"structure.element", "P1", "P2"}},
      {"p2_body_fitted", fsi, "--set structure.element=P2 --set fluid.method=body-fitted", {"structure.element", "P1", "penalised"}},
      {"max_iterations_negative", fsi, "--set coupling.max_iterations=-1", {"coupling.max_iterations", "integer"}},
      {"max_iterations_float", fsi, "--set coupling.max_iterations=2.5", {"coupling.max_iterations", "integer"}},
      {"solver_unknown", kValid, "--set contact.solver=gurobi", {"contact.solver", "active-set", "ipopt"}},
      {"mu_zero", fsi, "--set fluid.mu=0", {"fluid.mu", "[1e-30, 1e+30]"}},
      {"hF_too_large", fsi, "--set fluid.h=0.1", {"fluid.h", "(0, obstacle.r = 0.005]", "obstacle.r = 0.005, from case.toml"}},
      {"obstacle_outside_box", fsi, "--set fluid.H2=0.01 --set fluid.h=0.004", {"obstacle.r", "to the fluid box's bottom", "at least fluid.h/2"}},
      {"structure_longer_than_box", fsi, "--set structure.L=0.08 --set fluid.L1=0.07", {"structure.L", "fluid box"}},
      {"structure_taller_than_box", fsi, "--set fluid.H1=0.004", {"structure.H", "fluid box"}},
      {"fluid_mesh_too_fine", fsi, "--set fluid.h=1e-5", {"fluid.h", "limit of 4e+06", "2e+07 with fluid.linear_solver"}},
      {"fluid_mesh_too_fine_iterative", fsi, "--set fluid.h=1e-5 --set fluid.linear_solver=\"petsc-iterative\"", {"fluid.h", "limit of 2e+07"}},
      {"chi_unknown", fsi, "--set fluid.chi=exact", {"fluid.chi", "barycentre", "area-fraction"}},
      {"mu_nan", fsi, "--set fluid.mu=nan", {"fluid.mu", "finite"}},
      {"vmax_inf", fsi, "--set fluid.Vmax=inf", {"fluid.Vmax", "finite"}},
      {"f_nan", replace(kValid, "f = [0.0, -1.0e4]", "f = [nan, -1.0e4]"), "", {"structure.f", "finite"}},
      {"tol_negative_inf", fsi, "--set coupling.tol=-inf", {"coupling.tol", "finite"}},
      {"mesh_is_a_directory", replace(kValid, "h = 0.0014", "mesh = \".\""), "", {"structure.mesh", "a directory, not a mesh file; expected a Gmsh .msh file"}},
      {"fluid_mesh_missing", fsi, "--set fluid.mesh=nowhere.msh", {"fluid.mesh", "nowhere.msh"}},
      {"set_syntax", kValid, "--set omega=0.1", {"--set omega=0.1", "section.key=value"}},
      {"set_unknown_key", kValid, "--set structure.EE=1", {"--set structure.EE", "not a known key"}},
      {"missing_case_file", "", "missing.toml", {"missing.toml", "no such case file"}},
      {"case_file_is_a_directory", "", ".", {".: a directory, not a case file; expected a regular TOML file"}},
      {"case_file_is_a_device", "", "/dev/zero", {"/dev/zero: a character device, not a case file"}},
      {"missing_mesh_file", replace(kValid, "h = 0.0014", "mesh = \"nowhere.msh\""), "", {"structure.mesh", "nowhere.msh", "no such mesh file"}},
      {"truncated_mesh_file", replace(kValid, "h = 0.0014", "mesh = \"bad.msh\""), "", {"structure.mesh", "bad.msh"}},
      {"mesh_without_groups", replace(kValid, "h = 0.0014", "mesh = \"nogroups.msh\""), "", {"structure.mesh", "Gamma_D"}},
      {"output_not_writable", kValid + "[output]\ndir = \"/proc/fsicontact\"\n", "", {"output.dir", "/proc/fsicontact"}},
      {"out_not_writable", kValid, "--out /proc/fsicontact", {"output.dir", "/proc/fsicontact"}},
  };
}

// Values that crashed a library; [[obstacles]], holes and the box sides.
std::vector<BadInput> bad_values_and_obstacles() {
  return {
      // Values that reached a library and took the process down (issue 11, class 1).
      {"E_underflow", replace(kValid, "E = 3.0e5", "E = 1e-300"), "", {"structure.E", "[1e-30, 1e+30]"}},
      {"E_too_soft_for_the_loads", replace(kValid, "E = 3.0e5", "E = 1e-20"), "", {"structure.E", "strain", "<= 1e+06"}},
      {"E_underflow_into_ipopt", kValid, "--set structure.E=1e-300 --set contact.solver=ipopt", {"--set structure.E", "[1e-30, 1e+30]"}},
      {"load_overflow", replace(kValid, "f = [0.0, -1.0e4]", "f = [0.0, -1e300]"), "", {"structure.f", "out of range", "0 or a magnitude in [1e-30, 1e+30]"}},
      {"surface_load_overflow", kValid, "--set structure.h_N=[0,1e300]", {"--set structure.h_N", "out of range"}},
      {"length_overflow", kValid, "--set structure.L=1e31", {"--set structure.L", "[1e-30, 1e+30]"}},
      {"vmax_overflow", kValid + "[fluid]\nVmax = 1e31\n", "", {"fluid.Vmax", "0 or a magnitude"}},
      // SPEC §10: expressions in x, y, t, compiled when the case is read.
      {"vmax_unknown_variable", kValid + "[fluid]\nVmax = \"0.3*sin(pi*q)\"\n", "", {"case.toml: fluid.Vmax = \"0.3*sin(pi*q)\": unknown variable \"q\" at column 12; allowed: a number, or an expression in x, y, t with pi"}},
      {"fluid_f_syntax", kValid + "[fluid]\n", "--set 'fluid.f=[0, \"-981*(1 + x\"]'", {"--set fluid.f: fluid.f (the y component) = \"-981*(1 + x\": missing parenthesis at column 12", "an expression in x, y, t with pi"}},
      {"structure_f_unknown_function", kValid, "--set 'structure.f=[\"grav(x)\", 0]'", {"structure.f (the x component)", "unknown function \"grav\" at column 1"}},
      {"vmax_not_a_number_or_string", kValid + "[fluid]\nVmax = [8]\n", "", {"case.toml: fluid.Vmax must be a number or a string (an expression)"}},
      {"fluid_f_not_numbers_or_strings", kValid + "[fluid]\nf = [0, true]\n", "", {"case.toml: fluid.f must be an array of two numbers or expressions"}},
      {"navier_stokes_without_rho", kValid + "[fluid]\n", "--set fluid.model=navier-stokes", {"fluid.rho", "required", "navier-stokes"}},
      {"rho_zero", kValid + "[fluid]\nrho = 0\n", "", {"case.toml: fluid.rho", "[1e-30, 1e+30]"}},
      {"rho_negative", kValid + "[fluid]\n", "--set fluid.rho=-1000", {"fluid.rho", "[1e-30, 1e+30]"}},
      {"rho_nan", kValid + "[fluid]\n", "--set fluid.rho=nan", {"fluid.rho", "finite"}},
      {"navier_stokes_on_the_schur_path", kValid + "[fluid]\nmodel = \"navier-stokes\"\nrho = 1\nfactorization = \"schur\"\n", "", {"fluid.factorization", "symmetric", "\"whole\""}},
      {"newton_tol_zero", kValid + "[fluid]\n", "--set fluid.newton_tol=0", {"fluid.newton_tol", "[1e-15, 0.01]"}},
      {"newton_max_steps_zero", kValid + "[fluid]\n", "--set fluid.newton_max_steps=0", {"fluid.newton_max_steps", "[1, 1000]"}},
      {"petsc_on_the_schur_path", kValid + "[fluid]\nlinear_solver = \"petsc-mumps\"\nfactorization = \"schur\"\n", "", {"fluid.factorization", "\"mumps\"", "\"whole\""}},
      {"petsc_iterative_for_navier_stokes", kValid + "[fluid]\nmodel = \"navier-stokes\"\nrho = 1\nlinear_solver = \"petsc-iterative\"\n", "", {"fluid.linear_solver", "Stokes only", "\"petsc-mumps\""}},
      {"linear_solver_unknown", kValid + "[fluid]\n", "--set fluid.linear_solver=\"hypre\"", {"fluid.linear_solver", "petsc-iterative"}},
      {"linear_tol_too_large", kValid + "[fluid]\n", "--set fluid.linear_tol=0.5", {"fluid.linear_tol", "[1e-15, 0.01]"}},
      {"linear_max_iterations_zero", kValid + "[fluid]\n", "--set fluid.linear_max_iterations=0", {"fluid.linear_max_iterations", "[1, 100000]"}},
      {"krylov_unknown", kValid + "[fluid]\n", "--set fluid.krylov=\"cg\"", {"fluid.krylov", "\"gmres\", \"bicgstab\""}},
      {"viscous_form_unknown", kValid + "[fluid]\n", "--set fluid.viscous_form=laplace", {"fluid.viscous_form", "\"symmetric\", \"gradient\""}},
      // SPEC §12: [time], so far for the fluid alone.
      {"time_dt_zero", kValid + "[fluid]\n", "--set structure.shape=none --set fluid.rho=1 --set time.dt=0 --set time.t_end=1", {"time.dt", "[1e-30, 1e+30]"}},
      {"time_without_t_end", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\n", "--set structure.shape=none", {"case.toml: time.t_end", "required"}},
      {"time_dt_beyond_t_end", kValid + "[fluid]\nrho = 1\n[time]\ndt = 2\nt_end = 1\n", "--set structure.shape=none", {"time.dt = 2", "(0, time.t_end]"}},
      {"time_too_many_steps", kValid + "[fluid]\nrho = 1\n[time]\ndt = 1e-9\nt_end = 1\n", "--set structure.shape=none", {"time.t_end", "steps is over the limit", "at most"}},
      {"time_too_many_frames", kValid + "[fluid]\nrho = 1\n[time]\ndt = 1e-6\nt_end = 0.5\n", "--set structure.shape=none", {"time.output_every", "frames, over the limit", "at least 6"}},
      {"time_checkpoint_every_negative", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\nt_end = 1\ncheckpoint_every = -1\n", "--set structure.shape=none", {"time.checkpoint_every", "[0, 1000000000]"}},
      {"time_start_from_unknown", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\nt_end = 1\nstart_from = \"moving\"\n", "--set structure.shape=none", {"time.start_from", "\"rest\", \"steady\""}},
      {"time_steady_free_body", kValid + "[time]\ndt = 0.1\nt_end = 1\nstart_from = \"steady\"\n", "--set structure.rho=1 --set structure.clamped=false", {"time.start_from", "free body"}},
      {"time_scheme_unknown", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\nt_end = 1\nscheme = \"bdf3\"\n", "--set structure.shape=none", {"time.scheme", "\"bdf1\", \"bdf2\""}},
      {"time_with_a_structure_without_its_density", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\nt_end = 1\n", "", {"case.toml: structure.rho", "required with [time]"}},
      {"time_with_a_fluid_without_its_density", kValid + "[fluid]\n[time]\ndt = 0.1\nt_end = 1\n", "--set structure.rho=1", {"fluid.rho", "required with [time]"}},
      {"time_without_rho", kValid + "[fluid]\n[time]\ndt = 0.1\nt_end = 1\n", "--set structure.shape=none", {"fluid.rho", "required with [time]"}},
      {"time_unknown_key", kValid + "[fluid]\nrho = 1\n[time]\ndt = 0.1\nt_end = 1\ncheckpoint = 5\n", "--set structure.shape=none", {"time.checkpoint", "not a known key"}},
      {"fluid_probes_without_fluid", kValid + "[output]\nfluid_probes = [[0.01, 0.01]]\n", "", {"output.fluid_probes", "[fluid]"}},
      {"fluid_probe_in_a_hole", kValid + "[fluid]\nh = 0.004\n[output]\nfluid_probes = [[0.055, -0.012]]\n", "", {"output.fluid_probes[1]", "outside the fluid domain"}},
      {"fluid_probes_not_points", kValid + "[fluid]\nh = 0.004\n[output]\nfluid_probes = 3\n", "", {"output.fluid_probes", "array of [x, y] points"}},
      {"fluid_model_unknown", kValid + "[fluid]\n", "--set fluid.model=euler", {"fluid.model", "\"stokes\", \"navier-stokes\""}},
      {"thin_structure", kValid, "--set structure.H=1e-12", {"structure.h = 0.0014", "10 * structure.H", "from --set structure.H"}},
      {"fluid_too_strong_for_the_structure", kValid + "[fluid]\nh = 0.004\n", "--set structure.E=1e-5 --set structure.f=[0,0]", {"structure.E", "fluid's stresses"}},
      {"h_near_above_h", kValid + "[fluid]\nh = 0.004\nh_near = 0.005\n", "", {"fluid.h_near = 0.005", "fluid.h = 0.004"}},
      {"band_not_a_box", kValid + "[fluid]\nh = 0.004\nband = [0, 0, 1]\n", "", {"fluid.band", "four numbers"}},
      {"band_box_empty", kValid + "[fluid]\nh = 0.004\nband = [0.1, 0, 0.05, 0.1]\n", "", {"fluid.band", "empty box"}},
      {"band_box_outside_the_fluid_box", kValid + "[fluid]\nh = 0.004\nh_near = 0.002\nband = [1, 0, 2, 0.1]\n", "", {"fluid.band", "does not meet the fluid box", "fluid.h_near = 0.002"}},
      {"h_near_with_a_mesh_file", kValid + "[fluid]\nh = 0.004\nh_near = 0.002\nmesh = \"box.msh\"\n", "", {"fluid.h_near = 0.002", "fluid.mesh is set"}},
      {"h_obstacles_above_h", kValid + "[fluid]\nh = 0.004\nmesher = \"gmsh\"\nh_obstacles = 0.005\n", "", {"fluid.h_obstacles = 0.005", "fluid.h = 0.004"}},
      {"h_obstacles_with_the_lattice_mesher", kValid + "[fluid]\nh = 0.004\nh_obstacles = 0.002\n", "", {"fluid.h_obstacles = 0.002", "fluid.mesher = \"lattice\""}},
      {"h_obstacles_with_a_mesh_file", kValid + "[fluid]\nh = 0.004\nmesher = \"gmsh\"\nh_obstacles = 0.002\nmesh = \"box.msh\"\n", "", {"fluid.h_obstacles = 0.002", "fluid.mesh is set"}},
      {"h_obstacles_with_body_fitted", kValid + "[fluid]\nh = 0.004\nmesher = \"gmsh\"\nh_obstacles = 0.002\nmethod = \"body-fitted\"\n", "", {"fluid.h_obstacles = 0.002", "body-fitted"}},
      {"obstacle_ring_too_fine_for_the_limit", kValid + "[fluid]\nh = 0.004\nmesher = \"gmsh\"\n", "--set fluid.h_obstacles=1e-8", {"fluid.h", "triangles", "fluid.h_obstacles"}},
      {"band_too_fine_for_the_limit", kValid + "[fluid]\nh = 0.004\n", "--set fluid.h_near=1e-6", {"fluid.h", "triangles", "fluid.h_near"}},
      {"boundary_all_with_the_papers_gap", kValid, "--set contact.boundary=all", {"contact.boundary = \"all\"", "contact.gap = \"normal\""}},
      {"gap_unknown", kValid, "--set contact.gap=exact", {"contact.gap", "\"paper\", \"normal\""}},
      {"normal_gap_with_body_fitted", kValid + "[fluid]\nh = 0.004\n", "--set contact.gap=normal --set fluid.method=body-fitted", {"contact.gap = \"normal\"", "body-fitted"}},
      // [[obstacles]] (issue 13).
      {"obstacles_and_obstacle", kValid + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.005\n", "", {"obstacles", "[obstacle]", "not both"}},
      {"obstacles_with_the_papers_gap", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.005\n", "", {"contact.gap = \"paper\"", "[[obstacles]]"}},
      {"obstacle_polygon_without_points", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\n", "", {"obstacles[1].points", "missing"}},
      {"obstacle_polygon_two_points", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.01, -0.01]]\n", "", {"obstacles[1].points", "has 2 corners", "3 to 2000"}},
      {"obstacle_polygon_bad_entry", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.01, -0.01], 3]\n", "", {"obstacles[1].points", "not [x, y]"}},
      {"obstacle_polygon_self_intersecting", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.02, -0.02], [0.02, -0.01], [0, -0.03]]\n", "", {"obstacles[1].points", "not a simple polygon"}},
      {"obstacle_polygon_no_area", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.01, -0.01], [0.02, -0.01]]\n", "", {"obstacles[1].points", "encloses no area"}},
      {"obstacle_polygon_repeated_corner", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.01, -0.02], [0.01, -0.02], [0, -0.02]]\n", "", {"obstacles[1].points", "corner repeats"}},
      {"obstacle_polygon_nan", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"polygon\"\npoints = [[0, -0.01], [0.01, nan], [0, -0.02]]\n", "", {"obstacles[1].points", "out of range"}},
      {"obstacle_disk_without_r", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\n", "", {"obstacles[1]", "x0, y0 and r"}},
      {"obstacle_zero_normal", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"half-plane\"\npoint = [0, -0.01]\nnormal = [0, 0]\n", "", {"obstacles[1].normal", "is zero"}},
      {"obstacle_unknown_key", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.005\ngamma = 0.8\n", "", {"obstacles[1].gamma", "not a known key"}},
      {"structure_starts_inside_an_obstacle", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\nboundary = \"all\"\n[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = 0.0\nr = 0.005\n", "", {"inside an obstacle", "[[obstacles]]"}},
      {"obstacles_gamma_c_on_a_rectangle", replace(kValid, "[obstacle]\nx0 = 0.055\ny0 = -0.012\nr = 0.005\ngamma = 0.8\n", "") + "[contact]\ngap = \"normal\"\n[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.005\n", "", {"contact.boundary = \"Gamma_C\"", "\"all\""}},
      // [[obstacles]] as holes of the fluid box (SPEC §9).
      {"fsi_obstacle_half_plane", kFsiObstacles + "[[obstacles]]\nshape = \"half-plane\"\npoint = [0, -0.01]\nnormal = [0, 1]\n", "", {"obstacles[1].shape = \"half-plane\"", "contact problems only", "\"disk\" or \"polygon\" with a [fluid] section"}},
      {"fsi_obstacles_overlap", kFsiObstacles + kDisk + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.035\ny0 = -0.012\nr = 0.005\n", "", {"case.toml: obstacles[2] overlaps obstacles[1]", "fluid.h/2 = 0.002 apart"}},
      {"fsi_obstacles_too_close", kFsiObstacles + kDisk + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.0405\ny0 = -0.01\nr = 0.005\n", "", {"obstacles[2] comes within 0.0005 of obstacles[1]"}},
      {"fsi_obstacle_across_the_box_bottom", kFsiObstacles + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.498\nr = 0.005\n", "", {"obstacles[1].r = 0.005", "to the fluid box's bottom", "at least fluid.h/2"}},
      {"fsi_obstacle_outside_the_box", kFsiObstacles + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.6\ny0 = 0\nr = 0.005\n", "", {"obstacles[1].r", "right side x = fluid.L1"}},
      {"fsi_obstacle_smaller_than_hF", kFsiObstacles + "[[obstacles]]\nshape = \"disk\"\nx0 = 0.03\ny0 = -0.01\nr = 0.003\n", "", {"fluid.h = 0.004 is larger than obstacles[1]'s radius", "obstacles[1].r = 0.003"}},
      {"fsi_obstacles_not_the_fluid_meshs_hole", kFsiObstacles + kDisk, "--set fluid.mesh=box.msh", {"case.toml: fluid.mesh box.msh: its hole Sigma_5_1 has the edge", "off the boundary of obstacles[1] (a disk)"}, {{"box.msh", shipped("paper-7.2-box-h0.02.msh")}}},
      // Polygons as holes of the fluid box (SPEC §9).
      {"fsi_polygon_across_the_box_bottom", kFsiObstacles + polygon_obstacle("[0.02, -0.499], [0.04, -0.499], [0.03, -0.4]"), "", {"obstacles[1].points leaves 0.001 to the fluid box's bottom", "at least fluid.h/2 = 0.002"}},
      {"fsi_polygon_overlaps_a_disk", kFsiObstacles + kDisk + polygon_obstacle("[0.033, -0.012], [0.045, -0.012], [0.045, -0.004], [0.033, -0.004]"), "", {"case.toml: obstacles[2] overlaps obstacles[1]", "obstacles at least fluid.h/2 = 0.002 apart"}},
      {"fsi_polygon_around_a_disk", kFsiObstacles + kDisk + polygon_obstacle("[0.02, -0.03], [0.05, -0.03], [0.05, -0.006], [0.02, -0.006]"), "", {"obstacles[2] overlaps obstacles[1]"}},
      {"fsi_polygons_too_close", kFsiObstacles + polygon_obstacle("[0.02, -0.03], [0.04, -0.03], [0.03, -0.01]") + polygon_obstacle("[0.0405, -0.03], [0.06, -0.03], [0.05, -0.01]"), "", {"obstacles[2] comes within 0.0005 of obstacles[1]"}},
      {"fsi_polygon_bar_across_the_structure", kFsiObstacles + polygon_obstacle("[0.0301, -0.01], [0.0303, -0.01], [0.0303, 0.01], [0.0301, 0.01]"), "", {"the side (0.0303, -0.01) - (0.0303, 0.01) of obstacles[1] crosses the structure's boundary at rest"}},
      {"fsi_polygon_tip_into_the_structure", kFsiObstacles + polygon_obstacle("[0.0295, -0.01], [0.0305, -0.01], [0.03, 0.001]"), "", {"the corner (0.03, 0.001) of obstacles[1] lies inside the structure at rest"}},
      {"fsi_half_plane_body_fitted", kFsiObstacles + kDisk + "[[obstacles]]\nshape = \"half-plane\"\npoint = [0, -0.01]\nnormal = [0, 1]\n", "--set fluid.method=body-fitted", {"obstacles[2].shape = \"half-plane\"", "contact problems only"}},
      {"eps_rule_unknown", kValid + "[fluid]\nh = 0.004\n", "--set coupling.eps_rule=h^9", {"coupling.eps_rule", "h^p"}},
      {"method_unknown", kValid + "[fluid]\nh = 0.004\n", "--set fluid.method=immersed", {"fluid.method", "body-fitted"}},
      // The box sides (SPEC §10).
      {"side_unknown", kValid + "[fluid]\nh = 0.004\n", "--set fluid.top=inlet", {"--set fluid.top: fluid.top = \"inlet\" is not a known choice", "\"wall\", \"inflow\", \"outflow\""}},
      {"side_not_a_string", kValid + "[fluid]\nh = 0.004\nright = 1\n", "", {"case.toml: fluid.right must be a string"}},
      {"inflow_without_outflow", kValid + "[fluid]\nh = 0.004\n", "--set fluid.bottom=wall", {"case.toml: fluid.top", "without an outflow side", "the inflow has nowhere to go", "up to a constant", "at least one of fluid.left, fluid.bottom, fluid.right, fluid.top = \"outflow\""}},
      {"all_walls", kValid + "[fluid]\nh = 0.004\ntop = \"wall\"\nbottom = \"wall\"\n", "", {"case.toml: fluid.bottom", "left = \"wall\", bottom = \"wall\", right = \"wall\", top = \"wall\"", "up to a constant"}},
      {"inflow_into_the_clamped_side", kValid + "[fluid]\nh = 0.004\n", "--set fluid.left=inflow", {"fluid.left = \"inflow\"", "Gamma_D", "\"wall\" or \"outflow\""}},
      {"omega_just_above_one", kValid + "[fluid]\n", "--set coupling.omega=1.0000001", {"coupling.omega = 1.0000001 is out of range", "(0, 1]"}},
  };
}

// Geometry that died in meshing, output in the wrong place, keys against a mesh.
std::vector<BadInput> bad_geometry_and_outputs() {
  return {
      // Geometry that passed and then died in meshing (class 4).
      {"gamma_c_a_rounding_error_from_the_end", replace(replace(kValid, "r = 0.005", "r = 0.00625"), "gamma = 0.8", "gamma = 0.79999999999999"), "", {"obstacle.x0", "Gamma_C", "structure.h/20", "from the structure's end"}},
      {"gamma_c_at_the_clamped_end", replace(kValid, "x0 = 0.055", "x0 = 0.004"), "", {"obstacle.x0", "clamped end"}},
      {"gamma_c_without_a_vertex_inside", kValid, "--set obstacle.gamma=0.1", {"--set obstacle.gamma: obstacle.gamma = 0.1", "no longer than a mesh edge", "gamma > structure.h / (2 r) = 0.14"}},
      {"gamma_c_below_round_off", kValid, "--set obstacle.gamma=1e-300", {"obstacle.gamma = 1e-300", "gamma > structure.h / (2 r)"}},
      // Output in the wrong place (class 5).
      {"name_dot_dot", replace(kValid, "name = \"t\"", "name = \"..\""), "", {"case.toml: name", "not starting with '.'"}},
      {"name_hidden", replace(kValid, "name = \"t\"", "name = \".t\""), "", {"name", "not starting with '.'"}},
      {"name_too_long", replace(kValid, "name = \"t\"", "name = \"" + std::string(250, 'n') + "\""), "", {"name", "1 to 200"}},
      {"out_a_tab_from_a_toml_escape", kValid + "[output]\ndir = \"C:\\temp\"\n", "", {"output.dir", "U+0009", "tab"}},
      {"out_is_a_file", kValid, "--out case.toml", {"--out: output.dir = \"case.toml\" is a file"}},
      {"out_through_a_file", kValid, "--out case.toml/sub", {"--out: output.dir", "not a directory"}},
      {"out_component_too_long", kValid, "--out " + std::string(300, 'd'), {"output.dir", "component of 300 bytes"}},
      // Keys that contradict a given mesh (class 7).
      {"fluid_mesh_box_longer", kBoxCase, "--set fluid.L1=0.5", {"fluid.L1 = 0.5 contradicts fluid.mesh", "x = 0.41"}, {{"box.msh", shipped("paper-7.2-box-h0.02.msh")}}},
      {"fluid_mesh_box_taller", kBoxCase, "--set fluid.H1=0.6", {"fluid.H1 = 0.6 contradicts fluid.mesh"}, {{"box.msh", shipped("paper-7.2-box-h0.02.msh")}}},
      {"fluid_mesh_obstacle_elsewhere", kBoxCase, "--set obstacle.r=0.04", {"obstacle.r = 0.04 contradicts fluid.mesh", "Sigma_5"}, {{"box.msh", shipped("paper-7.2-box-h0.02.msh")}}},
      {"fluid_mesh_inflow_label_at_the_bottom", kBoxCase, "", {"fluid.mesh", "Sigma_4", "not on the top", "(fluid.top = \"inflow\")"},
       {{"box.msh", replace(replace(replace(shipped("paper-7.2-box-h0.02.msh"), "1 2 \"Sigma_2\"", "1 2 \"Sigma_X\""), "1 4 \"Sigma_4\"", "1 4 \"Sigma_2\""), "1 2 \"Sigma_X\"", "1 2 \"Sigma_4\"")}}},
      // A user's .msh with a defect that used to pass silently (class 6): exit 2
      // naming the file and the defect (tests/mesh/ has one test per defect).
      {"mesh_tangled", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "m.msh", "tangled"}, {{"m.msh", defect("tangled")}}},
      {"mesh_duplicate_node_tag", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "node tag 3 is defined twice"}, {{"m.msh", defect("duplicate-node")}}},
      {"mesh_without_the_domain_group", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "'Omega_S'"}, {{"m.msh", defect("no-domain-group")}}},
      {"mesh_second_order", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "6-node triangles"}, {{"m.msh", defect("second-order-triangle")}}},
      {"mesh_zero_area", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "zero area"}, {{"m.msh", defect("zero-area")}}},
      {"mesh_is_a_script", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "", {"structure.mesh", "not a Gmsh mesh file"}, {{"m.msh", "SystemCall \"touch pwned\";\n"}}},
      {"mesh_is_a_case_file", replace(kValid, "h = 0.0014", "mesh = \"case.toml\""), "", {"structure.mesh", "case.toml"}},
      {"structure_mesh_with_a_floating_part", replace(replace(kValid, "h = 0.0014", "mesh = \"floating.msh\""), "x0 = 0.055", "x0 = 0.015"), "", {"structure.mesh floating.msh", "not connected to Gamma_D"}, {{"floating.msh", floating_block_msh()}}},
  };
}

// A user's defective .msh, structure.shape and .geo scripts, output.probes.
std::vector<BadInput> bad_files_shapes_and_probes() {
  return {
      // structure.shape and .geo scripts (issue 13).
      {"shape_unknown", kValid, "--set structure.shape=circle", {"structure.shape", "\"rectangle\", \"mesh\", \"geo\""}},
      {"shape_mesh_without_a_file", kValid, "--set structure.shape=mesh", {"structure.shape = \"mesh\"", "needs the file structure.mesh"}},
      {"shape_rectangle_with_a_mesh", replace(kValid, "h = 0.0014", "mesh = \"m.msh\""), "--set structure.shape=rectangle", {"structure.shape = \"rectangle\"", "structure.mesh is given"}},
      {"none_without_a_fluid", kValid, "--set structure.shape=none", {"structure.shape = \"none\"", "[fluid]"}},
      {"none_with_a_mesh", replace(kValid, "h = 0.0014", "mesh = \"m.msh\"") + "[fluid]\n", "--set structure.shape=none", {"structure.shape = \"none\"", "structure.mesh is given"}},
      {"none_body_fitted", kValid + "[fluid]\nh = 0.004\n", "--set structure.shape=none --set fluid.method=body-fitted", {"fluid.method = \"body-fitted\"", "structure.shape = \"none\""}},
      {"none_band_width", kValid + "[fluid]\nh = 0.004\nh_near = 0.002\n", "--set structure.shape=none", {"fluid.band", "structure.shape = \"none\" has none"}},
      {"geo_and_mesh", kGeo, "--set structure.mesh=m.msh", {"structure.geo", "structure.mesh", "both"}},
      {"geo_missing", kGeo, "--set structure.geo=none.geo", {"structure.geo", "none.geo", "no such script file"}},
      {"geo_not_named_geo", kGeo, "--set structure.geo=case.toml", {"structure.geo", "extension .geo"}},
      {"geo_runs_a_program", kGeo, "", {"structure.geo", "s.geo:1: the command 'System'", "allowed: geometry"}, {{"s.geo", "System \"touch pwned\";\n" + kBar}}},
      {"geo_writes_a_file", kGeo, "", {"structure.geo", "s.geo:5: the command 'Printf'", "into a file"}, {{"s.geo", kBar + "Printf(\"%g\", 1) > \"leak.txt\";\n"}}},
      {"geo_saves_a_mesh", kGeo, "", {"structure.geo", "'Save'"}, {{"s.geo", kBar + "Mesh 2;\nSave \"x.msh\";\n"}}},
      {"geo_syntax_error", kGeo, "", {"structure.geo", "s.geo', line 2", "syntax error"}, {{"s.geo", "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0 0};\n"}}},
      {"geo_no_surface", kGeo, "", {"structure.geo", "defines no surface"}, {{"s.geo", "Point(1) = {0, 0, 0};\n"}}},
      {"geo_too_fine", kGeo, "--set structure.h=1e-5", {"structure.geo", "above the limit"}, {{"s.geo", kBar}}},
      {"geo_without_gamma_d", kGeo, "", {"structure.geo", "Gamma_D"}, {{"s.geo", replace(kBar, "Physical Curve(\"Gamma_D\") = {4};", "")}}},
      {"geo_unlabelled_edge", kGeo, "", {"structure.geo", "belongs to no boundary part"}, {{"s.geo", replace(kBar, "{1, 2, 3};", "{1, 2};")}}},
      {"geo_without_gamma_c_for_gamma_c", kGeo, "--set contact.boundary=Gamma_C", {"structure.geo", "no physical curve Gamma_C", "contact.boundary"}, {{"s.geo", kBar}}},
      {"geo_extent_contradicts_L", kGeo, "--set structure.L=0.2", {"structure.L = 0.2 contradicts structure.geo", "x = 0.1"}, {{"s.geo", kBar}}},
      {"geo_starts_inside_the_floor", replace(kGeo, "point = [0.0, -0.001]", "point = [0.0, 0.01]"), "", {"structure.geo s.geo", "inside an obstacle"}, {{"s.geo", kBar}}},
      {"geo_too_soft", kGeo, "--set structure.E=1e-20", {"structure.geo", "strain", "<= 1e+06"}, {{"s.geo", kBar}}},
      // output.probes (SPEC §11, issue 14): the form, then points of the structure only.
      {"probes_not_an_array", kValid, "--set output.probes=3", {"--set output.probes: output.probes must be an array", "[[x, y], ...]"}},
      {"probe_of_three_numbers", kValid, "--set 'output.probes=[[0.01, 0.002], [0.02, 0.002], [1, 2, 3]]'", {"--set output.probes: output.probes[3]", "not [x, y]", "at most 1000"}},
      {"probe_nan", kValid, "--set 'output.probes=[[nan, 0.002]]'", {"output.probes[1]", "finite"}},
      {"probes_too_many", kValid, "--set 'output.probes=[" + many_probes(1001) + "]'", {"output.probes", "has 1001 points", "at most 1000"}},
      {"probe_outside_the_structure", kValid, "--set 'output.probes=[[0.01, 0.002], [0.07, 0.002]]'", {"output.probes[2] = (0.07, 0.002)", "0.01 m outside the structure", "within 6.02e-11 m"}},
      {"probes_without_a_structure", kValid + "[fluid]\nh = 0.004\n", "--set structure.shape=none --set 'output.probes=[[0.01, 0.002]]'", {"output.probes", "structure.shape = \"none\" has none"}},
      {"structure_mesh_longer_than_L", replace(replace(kValid, "h = 0.0014", "mesh = \"beam.msh\""), "L = 0.06", "L = 0.07"), "", {"structure.L = 0.07 contradicts structure.mesh", "0.06"}, {{"beam.msh", shipped("paper-7.1-beam.msh")}}},
  };
}

std::vector<BadInput> bad_inputs() {
  std::vector<BadInput> all;
  for (auto part : {bad_keys, bad_values_and_obstacles, bad_geometry_and_outputs, bad_files_shapes_and_probes})
    for (BadInput& b : part()) all.push_back(std::move(b));
  return all;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, IsRejectedWithExitStatus2AndNothingWritten) {
  const BadInput& b = GetParam();
  const fs::path dir = testing::scratch_dir("bad-" + b.label);
  if (!b.case_text.empty()) testing::write_text(dir / "case.toml", b.case_text);
  testing::write_text(dir / "bad.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n");
  // A valid mesh file without physical groups.
  testing::write_text(dir / "nogroups.msh",
                      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n"
                      "0 0 0\n1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n"
                      "$EndElements\n");
  for (const auto& [name, text] : b.files) testing::write_text(dir / name, text);
  const auto listing = [&] {
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(e.path().string());
    return names;
  };
  const std::set<std::string> before = listing();
  const std::string target = b.case_text.empty() ? "" : "case.toml";
  const bool own_out = b.extra_args.find("--out") != std::string::npos ||
                       b.case_text.find("[output]") != std::string::npos;
  const testing::CliRun r =
      testing::run_cli("run " + target + " " + b.extra_args + (own_out ? "" : " --out result"), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  for (const auto& s : b.expected) EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(dir / "result")) << "output written for invalid input";
  EXPECT_EQ(listing(), before) << "a file or directory was created for invalid input";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Table, BadInputTest, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& param_info) { return param_info.param.label; });

}  // namespace
}  // namespace fsi::bad_input_test
