#include "run/setup_cache.hpp"

#include "common/format.hpp"
#include "run/fluid_band.hpp"
#include "run/mesh_checks.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

// build_structure_mesh reads structure.* and obstacle.*; build_fluid_mesh fluid.* and
// obstacle.*. The fluid mesh's key leaves out the keys only the solver reads, named
// here, so that a sweep over them meshes the box once; any other key, a new one
// included, remeshes: a forgotten key costs time, never a wrong mesh.
// The mesh files' names are appended as they are: json_text replaces bytes that are
// not UTF-8, so two such names could otherwise share a key.
namespace {

// [[obstacles]] as in summary.json (empty without them).
std::string obstacles_text(const Case& c) {
  const Json all = to_json(c);
  return all.contains("obstacles") ? json_text(all["obstacles"]) : std::string();
}

}  // namespace

// [[obstacles]] shape the contact constraint, and D's holes.
std::string structure_mesh_key(const Case& c) {
  return json_text(to_json(c.structure)) + json_text(to_json(c.obstacle)) + obstacles_text(c) + '\0' + c.structure.mesh;
}

std::string fluid_mesh_key(const Case& c) {
  Json geometry = to_json(*c.fluid);
  for (const char* solver_only : {"mu", "f", "Vmax", "chi", "factorization", "keep_far_factors_mb", "left", "bottom",
                                  "right", "top", "model", "rho", "newton_tol", "newton_max_steps", "viscous_form",
                                  "linear_solver", "linear_tol", "linear_max_iterations", "krylov"})
    geometry.erase(solver_only);
  return json_text(geometry) + json_text(to_json(c.obstacle)) + obstacles_text(c) + '\0' + c.fluid->mesh;
}

// make_structure reads structure.*, obstacle.* and contact.*; make_fluid fluid.*
// and the mesh (ε is set per row).
std::string structure_setup_key(const Case& c) {
  // Δt too: Newmark's operator A_S + (4/Δt²) M is the solver's (SPEC §12).
  return structure_mesh_key(c) + json_text(to_json(c.contact)) + (c.time ? "dt=" + shortest(c.time->dt) : "");
}

std::string fluid_setup_key(const Case& c) { return json_text(to_json(*c.fluid)) + fluid_mesh_key(c); }

const Mesh& SetupCache::structure_mesh(const Case& c) {
  const std::string key = structure_mesh_key(c);
  auto it = structure_meshes_.find(key);
  if (it == structure_meshes_.end()) it = structure_meshes_.emplace(key, build_structure_mesh(c)).first;
  check_structure_mesh(c, it->second);
  return it->second;
}

std::optional<std::array<double, 4>> SetupCache::band(const Case& c) {
  if (!band_needs_structure(c)) return fluid_band_box(c, nullptr);
  const std::string key = structure_setup_key(c) + json_text(to_json(*c.fluid));
  auto it = bands_.find(key);
  if (it == bands_.end()) it = bands_.emplace(key, *fluid_band_box(c, &structure(c))).first;
  return it->second;
}

// The band's box joins the key as numbers: two cases whose bands differ remesh.
const Mesh& SetupCache::fluid_mesh(const Case& c) {
  const std::optional<std::array<double, 4>> box = band(c);
  std::string key = fluid_mesh_key(c);
  if (box) key += json_text(Json(*box));
  auto it = fluid_meshes_.find(key);
  if (it == fluid_meshes_.end()) it = fluid_meshes_.emplace(key, build_fluid_mesh(c, box)).first;
  if (!c.fluid->mesh.empty()) check_fluid_mesh(c, it->second);
  check_fluid_probes_inside(c, it->second);
  return it->second;
}

StructureSetup& SetupCache::structure(const Case& c) {
  const std::string key = structure_setup_key(c);
  if (key != structure_key_ || !structure_.solver) {
    structure_ = StructureSetup{};
    structure_key_.clear();  // until the new setup exists
    structure_ = make_structure(c, structure_mesh(c), nullptr);
    structure_key_ = key;
  }
  return structure_;
}

FluidSetup& SetupCache::fluid(const Case& c) {
  const std::optional<std::array<double, 4>> box = band(c);
  const std::string key = fluid_setup_key(c) + (box ? json_text(Json(*box)) : std::string());
  if (key != fluid_key_ || !fluid_.stokes) {
    fluid_ = FluidSetup{};  // release the old factorisation before building the next
    fluid_key_.clear();
    fluid_ = make_fluid(c, fluid_mesh(c), c.coupling.eps);
    fluid_key_ = key;
  } else {
    fluid_.stokes->reset();
    fluid_.stokes->set_eps(c.coupling.eps);
  }
  return fluid_;
}

}  // namespace fsi
