#include "mesh/gmsh_io.hpp"

#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <unordered_map>

namespace fsi {
namespace {

// Gmsh keeps one global model: serialise access and initialise once.
std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

class GmshSession {
 public:
  GmshSession() : lock_(gmsh_mutex()) {
    static bool initialised = false;
    if (!initialised) {
      gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
      initialised = true;
    }
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
    gmsh::option::setNumber("General.NumThreads", 1);  // reproducible meshes
    gmsh::clear();
  }
  ~GmshSession() {
    try {
      gmsh::clear();
    } catch (...) {
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::lock_guard<std::mutex> lock_;
};

// Gmsh 4.8 reports errors by throwing a std::string; turn it into a MeshError.
template <class F>
auto gmsh_call(const std::string& context, F&& f) {
  try {
    return f();
  } catch (const std::string& what) {
    throw MeshError(context + ": " + what);
  } catch (const std::exception& e) {
    throw MeshError(context + ": " + e.what());
  }
}

// Collects the current Gmsh model into a Mesh. Triangles come from `surface_entities`
// (all 2D entities if empty); boundary edges from the named physical curves.
Mesh extract_mesh(const std::vector<int>& surface_entities,
                  const std::vector<std::pair<std::string, std::vector<int>>>& curves) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, param;
  gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, true, false);

  std::unordered_map<std::size_t, int> index;  // Gmsh node tag -> compact vertex index
  Mesh mesh;
  auto vertex = [&](std::size_t tag) {
    auto [it, inserted] = index.try_emplace(tag, mesh.num_vertices());
    if (inserted) {
      const auto pos = std::lower_bound(node_tags.begin(), node_tags.end(), tag);
      if (pos == node_tags.end() || *pos != tag) throw MeshError("element uses an unknown node");
      const std::size_t k = static_cast<std::size_t>(pos - node_tags.begin());
      mesh.vertices.emplace_back(coords[3 * k], coords[3 * k + 1]);
    }
    return it->second;
  };
  // getNodes returns tags in no guaranteed order: sort tags and coordinates together.
  {
    std::vector<std::size_t> order(node_tags.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return node_tags[a] < node_tags[b]; });
    std::vector<std::size_t> t2(order.size());
    std::vector<double> c2(3 * order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      t2[i] = node_tags[order[i]];
      for (int d = 0; d < 3; ++d) c2[3 * i + d] = coords[3 * order[i] + d];
    }
    node_tags.swap(t2);
    coords.swap(c2);
  }

  std::vector<int> surfaces = surface_entities;
  if (surfaces.empty()) {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, 2);
    for (const auto& [dim, tag] : ents) surfaces.push_back(tag);
  }
  for (int s : surfaces) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elems, nodes;
    gmsh::model::mesh::getElements(types, elems, nodes, 2, s);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] != 2)
        throw MeshError("only 3-node triangles are supported (found Gmsh element type " +
                        std::to_string(types[k]) + ")");
      for (std::size_t e = 0; e + 2 < nodes[k].size(); e += 3)
        mesh.triangles.push_back(
            {vertex(nodes[k][e]), vertex(nodes[k][e + 1]), vertex(nodes[k][e + 2])});
    }
  }
  for (const auto& [name, entities] : curves) {
    const int lab = mesh.add_label(name);
    for (int c : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elems, nodes;
      gmsh::model::mesh::getElements(types, elems, nodes, 1, c);
      for (std::size_t k = 0; k < types.size(); ++k) {
        if (types[k] != 1)
          throw MeshError("only 2-node boundary lines are supported on '" + name + "'");
        for (std::size_t e = 0; e + 1 < nodes[k].size(); e += 2)
          mesh.boundary_edges.push_back({{vertex(nodes[k][e]), vertex(nodes[k][e + 1])}, lab});
      }
    }
  }
  if (mesh.triangles.empty()) throw MeshError("the mesh has no triangles");
  try {
    orient_and_check(mesh);
  } catch (const std::runtime_error& e) {
    throw MeshError(e.what());
  }
  return mesh;
}

void mesh_2d(double h) {
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay (DEPENDENCIES.md)
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  gmsh::model::mesh::generate(2);
}

}  // namespace

Mesh generate_structure_mesh(const StructureGeometry& g) {
  GmshSession session;
  return gmsh_call("meshing the structure", [&] {
    namespace geo = gmsh::model::geo;
    gmsh::model::add("structure");
    const double h = g.h;
    // Bottom side split at the ends of Γ_C so that vertices sit exactly there.
    const int p0 = geo::addPoint(0, 0, 0, h), pc0 = geo::addPoint(g.xc_min, 0, 0, h),
              pc1 = geo::addPoint(g.xc_max, 0, 0, h), p1 = geo::addPoint(g.L, 0, 0, h),
              p2 = geo::addPoint(g.L, g.H, 0, h), p3 = geo::addPoint(0, g.H, 0, h);
    const int bottom_left = geo::addLine(p0, pc0), contact = geo::addLine(pc0, pc1),
              bottom_right = geo::addLine(pc1, p1), right = geo::addLine(p1, p2),
              top = geo::addLine(p2, p3), left = geo::addLine(p3, p0);
    const int loop = geo::addCurveLoop({bottom_left, contact, bottom_right, right, top, left});
    geo::addPlaneSurface({loop});
    geo::synchronize();
    mesh_2d(h);
    return extract_mesh({}, {{"Gamma_D", {left}},
                             {"Gamma_C", {contact}},
                             {"Gamma_N", {bottom_left, bottom_right, right, top}}});
  });
}

Mesh generate_fluid_mesh(const FluidGeometry& g) {
  GmshSession session;
  return gmsh_call("meshing the fluid box", [&] {
    namespace geo = gmsh::model::geo;
    gmsh::model::add("fluid");
    const double h = g.h;
    const int a = geo::addPoint(0, -g.H2, 0, h), b = geo::addPoint(g.L1, -g.H2, 0, h),
              c = geo::addPoint(g.L1, g.H1, 0, h), d = geo::addPoint(0, g.H1, 0, h);
    const int bottom = geo::addLine(a, b), right = geo::addLine(b, c), top = geo::addLine(c, d),
              left = geo::addLine(d, a);
    const int centre = geo::addPoint(g.x0, g.y0, 0, h);
    const int e = geo::addPoint(g.x0 + g.r, g.y0, 0, h), n = geo::addPoint(g.x0, g.y0 + g.r, 0, h),
              w = geo::addPoint(g.x0 - g.r, g.y0, 0, h), s = geo::addPoint(g.x0, g.y0 - g.r, 0, h);
    const std::vector<int> arcs = {geo::addCircleArc(e, centre, n), geo::addCircleArc(n, centre, w),
                                   geo::addCircleArc(w, centre, s), geo::addCircleArc(s, centre, e)};
    const int outer = geo::addCurveLoop({bottom, right, top, left});
    const int hole = geo::addCurveLoop(arcs);
    geo::addPlaneSurface({outer, hole});
    geo::synchronize();
    mesh_2d(h);
    return extract_mesh({}, {{"Sigma_1", {left}},
                             {"Sigma_2", {bottom}},
                             {"Sigma_3", {right}},
                             {"Sigma_4", {top}},
                             {"Sigma_5", arcs}});
  });
}

Mesh read_gmsh_file(const std::string& path, const std::vector<std::string>& boundary_groups,
                    const std::string& domain_group) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw MeshError(path + ": no such mesh file");
  if (!std::ifstream(path).good()) throw MeshError(path + ": cannot be read");
  GmshSession session;
  return gmsh_call(path, [&] {
    gmsh::open(path);  // Gmsh ignores some unreadable files silently: checked below
    std::map<std::string, std::vector<int>> curves_by_name;
    std::vector<int> surfaces;
    for (int dim : {1, 2}) {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      for (const auto& [d, tag] : groups) {
        std::string name;
        gmsh::model::getPhysicalName(d, tag, name);
        std::vector<int> ents;
        gmsh::model::getEntitiesForPhysicalGroup(d, tag, ents);
        if (d == 1) curves_by_name[name].insert(curves_by_name[name].end(), ents.begin(), ents.end());
        if (d == 2 && name == domain_group) surfaces.insert(surfaces.end(), ents.begin(), ents.end());
      }
    }
    std::vector<std::pair<std::string, std::vector<int>>> curves;
    for (const auto& name : boundary_groups) {
      auto it = curves_by_name.find(name);
      if (it == curves_by_name.end())
        throw MeshError("has no physical curve named '" + name + "' (required: " + [&] {
          std::string all;
          for (const auto& n : boundary_groups) all += (all.empty() ? "" : ", ") + n;
          return all;
        }() + ")");
      curves.emplace_back(name, it->second);
    }
    return extract_mesh(surfaces, curves);
  });
}

}  // namespace fsi
