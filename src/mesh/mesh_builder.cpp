#include "mesh/mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <utility>

#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

struct ElementKind {
  int gmsh_type, nodes;
};
constexpr ElementKind kLine{1, 2}, kTriangle{2, 3};
// Beyond this a squared length overflows; far beyond any physical size in metres.
constexpr double kMaxCoordinate = 1e150;
// z may differ from 0 by round-off only, relative to the mesh's extent in x and y.
constexpr double kPlanarTolerance = 1e-10;

// "6-node triangles (Gmsh element type 9)": the common types by name, others by number.
std::string type_name(int type) {
  static const std::map<int, std::string> names = {
      {1, "2-node lines"},        {2, "3-node triangles"},  {3, "4-node quadrangles"},
      {4, "4-node tetrahedra"},   {8, "3-node lines"},      {9, "6-node triangles"},
      {10, "9-node quadrangles"}, {15, "points"},           {16, "8-node quadrangles"},
      {20, "9-node triangles"},   {21, "10-node triangles"}};
  const auto it = names.find(type);
  return (it == names.end() ? "elements" : it->second) + " (Gmsh element type " +
         std::to_string(type) + ")";
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

// Gmsh repairs some defects while reading and only says so in its log: a duplicated
// node tag is "Skipping duplicate node N" (kept first in MSH 4, last in MSH 2).
void refuse_what_gmsh_repaired(const std::vector<std::string>& log) {
  for (const auto& line : log) {
    for (const char* what : {"node", "element"}) {
      const std::string key = std::string("Skipping duplicate ") + what + " ";
      const auto at = line.find(key);
      if (at != std::string::npos)
        throw MeshError(std::string(what) + " tag " + line.substr(at + key.size()) +
                        " is defined twice");
    }
    if (line.find("Skipping") != std::string::npos)
      throw MeshError("Gmsh skipped part of the file: " + line);
    // Strict: a reader's warning means the file is not what it says it is (measured:
    // "Min/Max node tags reported in section header are wrong").
    for (const char* level : {"Error: ", "Warning: "})
      if (line.rfind(level, 0) == 0)
        throw MeshError(std::string("Gmsh ") + (level[0] == 'E' ? "reported an error" : "warned") +
                        ": " + line.substr(std::strlen(level)));
  }
}

// Node tag → position in the raw arrays. Gmsh numbers nodes densely as a rule
// (its log says "Vertex numbering is dense"): then a direct table, else a sorted one.
class NodeTable {
 public:
  explicit NodeTable(const RawMesh& raw) : raw_(raw) {
    const std::size_t n = raw.node_tags.size();
    if (raw.coords.size() != 3 * n)
      throw MeshError("the Gmsh child process sent a malformed reply (node coordinates)");
    const std::size_t max_tag =
        n == 0 ? 0 : *std::max_element(raw.node_tags.begin(), raw.node_tags.end());
    dense_ = max_tag <= 2 * n + 1024;  // the table stays O(n)
    if (dense_) {
      table_.assign(max_tag + 1, kNone);
      for (std::size_t i = 0; i < n; ++i) {
        if (table_[raw.node_tags[i]] != kNone) defined_twice(raw.node_tags[i]);
        table_[raw.node_tags[i]] = i;
      }
      return;
    }
    order_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) order_.push_back({raw.node_tags[i], i});
    std::sort(order_.begin(), order_.end());
    for (std::size_t i = 1; i < order_.size(); ++i)
      if (order_[i].first == order_[i - 1].first) defined_twice(order_[i].first);
  }
  std::size_t size() const { return raw_.node_tags.size(); }
  // Position of `tag`, or throws naming the element that uses it.
  std::size_t find(std::size_t tag, std::size_t element) const {
    std::size_t position = kNone;
    if (dense_ && tag < table_.size()) position = table_[tag];
    if (!dense_) {
      const auto it =
          std::lower_bound(order_.begin(), order_.end(), std::pair{tag, std::size_t{0}});
      if (it != order_.end() && it->first == tag) position = it->second;
    }
    if (position == kNone)
      throw MeshError("element " + std::to_string(element) + " uses node " + std::to_string(tag) +
                      ", which the file does not define");
    return position;
  }
  const double* coords(std::size_t position) const { return &raw_.coords[3 * position]; }

 private:
  static constexpr std::size_t kNone = ~std::size_t{0};
  [[noreturn]] static void defined_twice(std::size_t tag) {
    throw MeshError("node tag " + std::to_string(tag) + " is defined twice");
  }
  const RawMesh& raw_;
  bool dense_ = false;
  std::vector<std::size_t> table_;                          // dense: tag → position
  std::vector<std::pair<std::size_t, std::size_t>> order_;  // else: (tag, position), sorted
};

const RawGroup* find_group(const RawMesh& raw, int dim, const std::string& name) {
  for (const auto& g : raw.groups)
    if (g.dim == dim && g.name == name) return &g;
  return nullptr;
}

// Every required group present with the right dimension; one message for all missing.
void require_groups(const RawMesh& raw, const std::vector<std::string>& curves,
                    const std::string& surface) {
  std::vector<std::string> missing;
  auto need = [&](int dim, const std::string& name) {
    if (find_group(raw, dim, name)) return;
    if (find_group(raw, 3 - dim, name))
      throw MeshError("'" + name + "' is a physical " + (dim == 1 ? "surface" : "curve") +
                      "; it must be a physical " + (dim == 1 ? "curve" : "surface"));
    missing.push_back(name);
  };
  need(2, surface);
  for (const auto& c : curves) need(1, c);
  if (!missing.empty())
    throw MeshError("has no physical group named " + quoted_list(missing) +
                    " (required: surface '" + surface + "'; curves " + quoted_list(curves) + ")");
}

// The blocks of a group's entities, each checked to hold only `type`.
std::vector<const RawElements*> blocks_of(const RawMesh& raw, const RawGroup& group,
                                          ElementKind kind_wanted) {
  const std::string kind = group.dim == 2 ? "surface" : "curve";
  std::vector<const RawElements*> out;
  std::size_t count = 0;
  std::set<int> seen;  // groups merged by name may list an entity twice
  for (int entity : group.entities) {
    if (!seen.insert(entity).second) continue;
    for (const auto& b : raw.elements) {
      if (b.dim != group.dim || b.entity != entity || b.tags.empty()) continue;
      if (b.gmsh_type != kind_wanted.gmsh_type)
        throw MeshError("physical " + kind + " '" + group.name + "' holds " +
                        type_name(b.gmsh_type) + ", element " + std::to_string(b.tags.front()) +
                        " first; only " + type_name(kind_wanted.gmsh_type) +
                        " are supported there");
      if (b.nodes_per_element != kind_wanted.nodes ||
          b.nodes.size() != b.tags.size() * static_cast<std::size_t>(kind_wanted.nodes))
        throw MeshError("the Gmsh child process sent a malformed reply (element nodes)");
      out.push_back(&b);
      count += b.tags.size();
    }
  }
  if (count == 0) throw MeshError("physical " + kind + " '" + group.name + "' holds no elements");
  return out;
}

class Builder {
 public:
  explicit Builder(const RawMesh& raw) : nodes_(raw), vertex_of_(nodes_.size(), -1) {}

  void add_triangles(const RawElements& b) {
    for (std::size_t e = 0; e < b.tags.size(); ++e) {
      const std::size_t* n = &b.nodes[3 * e];
      out_.mesh.triangles.push_back(
          {vertex(n[0], b.tags[e]), vertex(n[1], b.tags[e]), vertex(n[2], b.tags[e])});
      out_.origin.triangle_tags.push_back(b.tags[e]);
      out_.origin.triangle_surfaces.push_back(b.entity);
    }
  }
  void add_lines(const RawElements& b, int label) {
    for (std::size_t e = 0; e < b.tags.size(); ++e) {
      const std::size_t* n = &b.nodes[2 * e];
      out_.mesh.boundary_edges.push_back(
          {{vertex(n[0], b.tags[e]), vertex(n[1], b.tags[e])}, label});
      out_.origin.edge_tags.push_back(b.tags[e]);
    }
  }
  Mesh& mesh() { return out_.mesh; }
  BuiltMesh finish() {
    check_planar();
    return std::move(out_);
  }

 private:
  // Compact index of a node, numbered in order of first use.
  int vertex(std::size_t tag, std::size_t element) {
    const std::size_t position = nodes_.find(tag, element);
    int& index = vertex_of_[position];
    if (index < 0) {
      index = out_.mesh.num_vertices();
      const double* c = nodes_.coords(position);
      for (int d = 0; d < 3; ++d)
        if (!(std::abs(c[d]) <= kMaxCoordinate))
          throw MeshError("node " + std::to_string(tag) + " has the coordinate " + number(c[d]) +
                          "; allowed: finite, of magnitude at most 1e150");
      out_.mesh.vertices.emplace_back(c[0], c[1]);
      z_.push_back(c[2]);
      out_.origin.node_tags.push_back(tag);
    }
    return index;
  }
  void check_planar() const {
    double extent = 0;
    for (int d = 0; d < 2; ++d) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& p : out_.mesh.vertices) lo = std::min(lo, p[d]), hi = std::max(hi, p[d]);
      extent = std::max(extent, hi - lo);
    }
    for (std::size_t v = 0; v < z_.size(); ++v)
      if (std::abs(z_[v]) > kPlanarTolerance * extent)
        throw MeshError("node " + std::to_string(out_.origin.node_tags[v]) +
                        " has z = " + number(z_[v]) + "; the mesh must lie in the plane z = 0");
  }

  NodeTable nodes_;
  std::vector<int> vertex_of_;  // node position → vertex index, -1 until first used
  std::vector<double> z_;
  BuiltMesh out_;
};

}  // namespace

BuiltMesh build_mesh(const RawMesh& raw, const std::vector<std::string>& boundary_groups,
                     const std::string& domain_group) {
  refuse_what_gmsh_repaired(raw.log);
  require_groups(raw, boundary_groups, domain_group);
  Builder builder(raw);
  for (const RawElements* b : blocks_of(raw, *find_group(raw, 2, domain_group), kTriangle))
    builder.add_triangles(*b);
  for (const auto& name : boundary_groups) {
    const int label = builder.mesh().add_label(name);
    for (const RawElements* b : blocks_of(raw, *find_group(raw, 1, name), kLine))
      builder.add_lines(*b, label);
  }
  return builder.finish();
}

}  // namespace fsi
