// Every case key reaches summary.json's parameters, and every key a setup reads is
// in that setup's cache key (issue 11: fluid.factorization and keep_far_factors_mb
// were in neither, so a sweep row could run with another row's solver).
#include <gtest/gtest.h>

#include <map>

#include "common/format.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/setup_cache.hpp"
#include "run/outputs/summary.hpp"

namespace fsi::setup_keys_test {
namespace {

// A valid value different from the §7.2 default, for each key: numbers 1% larger.
std::string other_value(const std::string& key) {
  static const std::map<std::string, std::string> special = {{"name", "other"},
                                                             {"structure.mesh", "m.msh"},
                                                             {"structure.geo", "s.geo"},
                                                             {"structure.f", "[1, -2]"},
                                                             {"structure.h_N", "[1, 2]"},
                                                             {"fluid.mesh", "b.msh"},
                                                             {"fluid.f", "[1, -2]"},
                                                             {"fluid.chi", "area-fraction"},
                                                             {"fluid.factorization", "whole"},
                                                             {"coupling.max_iterations", "7"},
                                                             {"coupling.scheme", "aitken"},
                                                             {"contact.solver", "ipopt"},
                                                             {"output.dir", "elsewhere"},
                                                             {"output.png", "false"},
                                                             {"output.vtu", "false"},
                                                             {"fluid.h_near", "0.005"},
                                                             {"fluid.h_obstacles", "0.005"},
                                                             {"fluid.method", "body-fitted"},
                                                             {"coupling.eps_rule", "h^2"},
                                                             {"contact.gap", "normal"},
                                                             {"contact.boundary", "all"},
                                                             {"fluid.left", "outflow"},
                                                             {"fluid.bottom", "wall"},
                                                             {"fluid.right", "outflow"},
                                                             {"fluid.top", "wall"},
                                                             {"output.probes", "[[0.1, 0.01]]"},
                                                             {"output.fluid_probes", "[[0.1, 0.1]]"},
                                                             {"structure.model", "neo-hookean"},
                                                             {"coupling.force", "large"},
                                                             {"coupling.force_sampling", "2"},
                                                             {"structure.element", "P2"},
                                                             {"structure.mesher", "gmsh"},
                                                             {"fluid.mesher", "gmsh"},
                                                             {"output.vtu_format", "zlib"},
                                                             {"fluid.model", "navier-stokes"},
                                                             {"fluid.rho", "1000"},
                                                             {"fluid.newton_max_steps", "7"},
                                                             {"fluid.viscous_form", "gradient"},
                                                             {"fluid.element", "taylor-hood"},
                                                             {"time.dt", "0.5"},
                                                             {"time.t_end", "3"},
                                                             {"time.scheme", "bdf2"},
                                                             {"time.output_every", "2"},
                                                             {"time.checkpoint_every", "2"},
                                                             {"time.start_from", "steady"},
                                                             {"time.convection", "semi-implicit"},
                                                             {"structure.rho", "1000"},
                                                             {"structure.v0", "[0.1, 0]"},
                                                             {"structure.mass", "consistent"},
                                                             {"coupling.reuse", "3"},
                                                             {"fluid.linear_solver", "petsc-mumps"},
                                                             {"fluid.krylov", "bicgstab"}};
  auto it = special.find(key);
  if (it != special.end()) return it->second;
  const Json defaults = to_json(load_case(""));
  const auto dot = key.find('.');
  return shortest(1.01 * defaults[key.substr(0, dot)][key.substr(dot + 1)].get<double>());
}

// A key valid only beside another (contact.boundary = "all" needs contact.gap =
// "normal"): both the changed case and its base get the companion, so the difference
// is the key's own.
std::vector<std::string> companions(const std::string& key) {
  if (key == "contact.boundary") return {"contact.gap=normal"};
  if (key == "fluid.bottom") return {"fluid.right=outflow"};  // an outflow side remains
  if (key == "fluid.model") return {"fluid.rho=1"};                 // Navier–Stokes needs its density
  if (key == "fluid.h_obstacles") return {"fluid.mesher=gmsh"};      // a Gmsh size field
  if (key == "fluid.element") return {"structure.shape=none"};       // Taylor–Hood: the fluid alone
  if (key.rfind("time.", 0) == 0)  // SPEC §12: so far the fluid alone, with its density
    return {"structure.shape=none", "fluid.rho=1", "time.dt=1", "time.t_end=2"};
  return {};
}

Case changed(const std::string& key) {
  std::vector<std::string> sets = companions(key);
  sets.push_back(key + "=" + other_value(key));
  return load_case("", sets);
}

TEST(SetupKeys, EveryCaseKeyIsInTheParameters) {
  const std::vector<std::string> keys = case_keys();
  EXPECT_GE(keys.size(), 30u);
  for (const std::string& key : keys) {
    if (key == "name" || key == "output.dir") continue;  // a name renames; a dir moves
    if (key == "structure.shape") continue;  // follows structure.mesh and .geo: it cannot change alone
    if (key == "structure.clamped") continue;  // false needs [time] without [fluid]: the next test
    const Case base = load_case("", companions(key)), c = changed(key);
    EXPECT_NE(to_json(c).dump(), to_json(base).dump()) << key << " is missing from summary.json's parameters";
  }
}

// structure.clamped = false is valid only in a time run of the structure alone (SPEC §12).
TEST(SetupKeys, StructureClampedIsInTheParametersAndTheSetupKey) {
  const std::string bar = std::string(FSICONTACT_SOURCE_DIR) + "/cases/bar-impact.toml";
  const Case free_body = load_case(bar), clamped = load_case(bar, {"structure.clamped=true"});
  EXPECT_NE(to_json(free_body).dump(), to_json(clamped).dump());
  EXPECT_NE(structure_setup_key(free_body), structure_setup_key(clamped));
}

TEST(SetupKeys, EverySectionKeyAChangesItsSetupKey) {
  for (const std::string& key : case_keys()) {
    const std::string section = key.substr(0, key.find('.'));
    if (section == "coupling" || section == "output" || section == "name") continue;  // set per row, or no setup
    if (key == "structure.shape" || key == "structure.clamped") continue;  // follows .mesh and .geo; the test above
    const Case base = load_case("", companions(key)), c = changed(key);
    if (section == "fluid" || section == "obstacle") {
      EXPECT_NE(fluid_setup_key(c), fluid_setup_key(base)) << key;
    }
    if (section == "structure" || section == "obstacle" || section == "contact") {
      EXPECT_NE(structure_setup_key(c), structure_setup_key(base)) << key;
    }
  }
}

// The inflow belongs to the label Σ4, not to the line y = H1: on a mesh whose Σ4 is
// not at the case's H1, it used to vanish silently (zero velocity, "converged").
TEST(SetupKeys, TheInflowIsAppliedOnTheLabelSigma4) {
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {0.5, 0.7}, {1, 0.7}, {0, 0.7}};
  m.triangles = {{0, 1, 3}, {0, 3, 2}, {0, 2, 4}};
  m.add_label("Sigma_1"), m.add_label("Sigma_3"), m.add_label("Sigma_5");
  const int top = m.add_label("Sigma_4");
  m.boundary_edges = {{{4, 2}, top}, {{2, 3}, top}};
  FluidParams f;
  f.L1 = 1.0;
  f.H1 = 0.5;  // not where Σ4 is
  f.Vmax = 2.0;
  const FluidBoundaryConditions bc = box_boundary_conditions(m, f);
  ASSERT_EQ(bc.dirichlet_values.size(), 1u);
  EXPECT_EQ(bc.dirichlet_values[0].first, top);
  EXPECT_DOUBLE_EQ(bc.dirichlet_values[0].second(m.vertices[2]).y(), -2.0);  // Vmax·4x(x − L1)/L1² at x = 1/2
}

}  // namespace
}  // namespace fsi::setup_keys_test
