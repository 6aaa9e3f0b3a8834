#include "mesh/gmsh_io.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "common/input_file.hpp"
#include "mesh/gmsh_child.hpp"
#include "mesh/geo_script.hpp"
#include "mesh/gmsh_model.hpp"
#include "mesh/mesh_builder.hpp"
#include "mesh/mesh_validation.hpp"

namespace fsi {
namespace {

// `optional_groups` present in `raw` are built like the required ones; the absent
// become empty labels, so that the solvers find every label they ask for.
Mesh build_and_validate(RawMesh raw, double unit, std::vector<std::string> boundary_groups,
                        const std::string& domain_group, const std::vector<std::string>& optional_groups = {}) {
  if (unit != 1)
    for (double& c : raw.coords) c *= unit;
  for (const auto& name : optional_groups)
    if (std::any_of(raw.groups.begin(), raw.groups.end(), [&](const RawGroup& g) { return g.dim == 1 && g.name == name; }))
      boundary_groups.push_back(name);
  BuiltMesh built = build_mesh(raw, boundary_groups, domain_group);
  orient_and_validate(built.mesh, built.origin);
  for (const auto& name : optional_groups) built.mesh.add_label(name);
  return std::move(built.mesh);
}

Mesh generate(const std::string& doing, const std::function<RawMesh()>& mesher, double unit,
              const std::vector<std::string>& boundary_groups, const std::string& domain_group,
              const GmshLimits& limits, const std::vector<std::string>& optional_groups = {}) {
  gmsh_plugin();  // loaded and initialised here, before the fork
  const std::size_t memory = physical_memory();
  const std::vector<char> bytes = run_in_child(
      [&] { return encode(mesher()); },
      {doing, "it may use this machine's memory, " + std::to_string(memory >> 20) + " MB"},
      {limits.seconds, memory});
  try {
    return build_and_validate(decode(bytes), unit, boundary_groups, domain_group, optional_groups);
  } catch (const MeshError& e) {
    throw MeshError("Gmsh made an unusable mesh while " + doing + ": " + e.what());
  }
}

// Gmsh's open() picks a reader by the extension (.stl, .step, .brep, .png, .py, ...
// whatever the content), else by the first line, and runs anything that does not
// start with "$MeshFormat" as a .geo script, SystemCall included, whatever the
// extension (measured, Gmsh 4.8.4; leading blank lines already make it a script).
// A data file must never run as code: only a .msh starting with "$MeshFormat".
void check_mesh_file(const std::string& path) {
  namespace fs = std::filesystem;
  if (const std::string problem = input_file_problem(path, "mesh", "a Gmsh .msh file"); !problem.empty())
    throw MeshError(path + ": " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot be read");
  if (fs::path(path).extension() != ".msh")
    throw MeshError(path + ": a mesh file must be a Gmsh .msh file (the extension .msh)");
  const std::string magic = "$MeshFormat";
  std::string head(magic.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (head != magic)
    throw MeshError(path + ": is not a Gmsh mesh file (its first line must be $MeshFormat)");
}

}  // namespace

Mesh gmsh_structure_mesh(const StructureGeometry& g, const GmshLimits& limits) {
  const double u = reference_length(std::max(std::abs(g.L), std::abs(g.H)));
  const StructureGeometry scaled{g.L / u, g.H / u, g.xc_min / u, g.xc_max / u, g.h / u};
  return generate(
      "meshing the structure", [&] { return gmsh_plugin().mesh_structure(scaled); }, u,
      {"Gamma_D", "Gamma_C", "Gamma_N"}, "Omega_S", limits);
}

namespace {

// The box scaled by 1/u (Gmsh meshes in units of u), and the labels of its sides and
// holes: Sigma_5_1, Sigma_5_2, ... for FluidGeometry::holes, else Sigma_5.
FluidGeometry scaled_box(const FluidGeometry& g, double u, std::vector<std::string>& labels) {
  FluidGeometry scaled{g.L1 / u, g.H1 / u, g.H2 / u, g.x0 / u, g.y0 / u, g.r / u, g.h / u, g.h_near / u, g.band,
                      g.h_holes / u};
  for (double& b : scaled.band) b /= u;
  labels = {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4"};
  if (!g.holes) {
    labels.push_back("Sigma_5");
    return scaled;
  }
  scaled.holes.emplace();
  for (const FluidHole& d : *g.holes) {
    FluidHole hole{d.x0 / u, d.y0 / u, d.r / u};
    for (const Point& p : d.corners) hole.corners.push_back(p / u);
    scaled.holes->push_back(std::move(hole));
    labels.push_back("Sigma_5_" + std::to_string(scaled.holes->size()));
  }
  return scaled;
}

}  // namespace

Mesh gmsh_fluid_mesh(const FluidGeometry& g, const GmshLimits& limits) {
  const double u = reference_length(std::max(std::abs(g.L1), std::abs(g.H1) + std::abs(g.H2)));
  std::vector<std::string> labels;
  const FluidGeometry scaled = scaled_box(g, u, labels);
  return generate(
      "meshing the fluid box", [&] { return gmsh_plugin().mesh_fluid(scaled); }, u, labels, "D",
      limits);
}

Mesh generate_fluid_mesh_around(const BodyFittedGeometry& g) {
  return generate_fluid_mesh_around(g, {});
}

Mesh generate_fluid_mesh_around(const BodyFittedGeometry& g, const GmshLimits& limits) {
  if (g.outline.size() < 3) throw MeshError("the structure's outline needs at least two segments");
  const FluidGeometry& b = g.box;
  const double u = reference_length(std::max(std::abs(b.L1), std::abs(b.H1) + std::abs(b.H2)));
  std::vector<std::string> labels;
  BodyFittedGeometry scaled{scaled_box(b, u, labels), g.outline};
  for (Point& p : scaled.outline) p /= u;
  labels.push_back("Gamma_u");
  return generate(
      "meshing the fluid around the structure",
      [&] { return gmsh_plugin().mesh_fluid_around(scaled); }, u, labels, "D", limits);
}

Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group) {
  return read_gmsh_file(path, boundary_groups, domain_group, {});
}

Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group, const GmshLimits& limits,
                    const std::vector<std::string>& optional_groups) {
  check_mesh_file(path);
  // Gmsh needs ~3 bytes of memory per byte of .msh (measured: 112 MB peak for a
  // 21 MB file, 51 MB of it the library); a header promising more than the file
  // holds must fail fast instead of filling the machine (3e8 nodes: 2.4 GB).
  std::error_code ec;
  const std::size_t size = std::filesystem::file_size(path, ec);
  const std::size_t budget = std::min<std::size_t>((1u << 30) + 16 * size, physical_memory());
  const ChildTask task{"reading it", "a count in its header promises more than the file holds (" +
                                         std::to_string(size) + " bytes; the reader may use " +
                                         std::to_string(budget >> 20) + " MB)"};
  try {
    gmsh_plugin();
    const std::vector<char> bytes = run_in_child([&] { return encode(gmsh_plugin().read(path)); },
                                                 task, {limits.seconds, budget});
    return build_and_validate(decode(bytes), 1, boundary_groups, domain_group, optional_groups);
  } catch (const MeshError& e) {
    throw MeshError(path + ": " + e.what());
  }
}

Mesh mesh_geo_script(const std::string& path, double h, double max_triangles,
                     const std::vector<std::string>& boundary_groups, const std::vector<std::string>& optional_groups,
                     const std::string& domain_group, const GmshLimits& limits) {
  const ScriptGeometry g{path, read_geo_script(path), h, max_triangles};
  try {
    return generate(
        "running and meshing it", [&] { return gmsh_plugin().mesh_script(g, forbid_side_effects); },
        1, boundary_groups, domain_group, limits, optional_groups);
  } catch (const MeshError& e) {
    throw MeshError(path + ": " + e.what());
  }
}

}  // namespace fsi
