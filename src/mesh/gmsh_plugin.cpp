// libfsicontact_gmsh.so: the Gmsh SDK behind the table of gmsh_model.hpp.
#include <gmsh.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_model.hpp"

namespace fsi {
namespace {

// Options for this child's work (the parent's Gmsh keeps its own).
void configure_gmsh(int verbosity) {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", verbosity);
  // One thread: libgomp is not fork-safe (measured: after the parent has run an
  // OpenMP region, the child hangs in its first region with two threads); one thread
  // also keeps the meshes reproducible.
  gmsh::option::setNumber("General.NumThreads", 1);
  for (const char* o : {"Mesh.MaxNumThreads1D", "Mesh.MaxNumThreads2D", "Mesh.MaxNumThreads3D"})
    gmsh::option::setNumber(o, 1);
  gmsh::option::setNumber("General.ExpertMode", 1);  // no "very large mesh, continue?" prompt
}

// Frontal-Delaunay (6) with one smoothing pass: the paper's uniform meshes, which
// Table 1's reproduction was measured on. Band meshes (fluid.h_near) use Delaunay (5)
// without smoothing: measured by bench/mesh_bench on §7.2 (docs/performance.md,
// "Meshing"), 2.6x faster at h_near = 0.001 (6 µs a triangle against 15), the
// smallest angle 26° against 34°, and max |u| 20 µm (0.05 %) apart, against a
// discretisation error near 1 % there.
struct MeshOptions {
  int algorithm = 6;
  int smoothing = 1;
};

void mesh_2d(double h, MeshOptions options = {}) {
  gmsh::option::setNumber("Mesh.Algorithm", options.algorithm);
  gmsh::option::setNumber("Mesh.Smoothing", options.smoothing);
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::mesh::generate(2);
}

// The band refinement (FluidGeometry::h_near): a Box field, h_near inside the band,
// h beyond the transition. Its tag.
int add_band_field(const FluidGeometry& g) {
  namespace field = gmsh::model::mesh::field;
  const int box = field::add("Box");
  field::setNumber(box, "VIn", g.h_near);
  field::setNumber(box, "VOut", g.h);
  field::setNumber(box, "XMin", g.band[0]);
  field::setNumber(box, "YMin", g.band[1]);
  field::setNumber(box, "XMax", g.band[2]);
  field::setNumber(box, "YMax", g.band[3]);
  field::setNumber(box, "ZMin", -1);
  field::setNumber(box, "ZMax", 1);
  field::setNumber(box, "Thickness", (g.h - g.h_near) / kBandGrowth);
  return box;
}

void add_elements(RawMesh& raw, int dim, int entity) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
  for (std::size_t k = 0; k < types.size(); ++k) {
    // Nodes per element from the lists themselves, not getElementProperties: that call
    // builds Gmsh's polynomial bases with Eigen, whose inline functions resolve to our
    // executable's instantiations, and under AddressSanitizer (handmade aligned
    // malloc) Gmsh then freed our allocation with free(): "bad-free" in every child.
    const int num_nodes = tags[k].empty() ? 0 : static_cast<int>(nodes[k].size() / tags[k].size());
    raw.elements.push_back(
        {dim, entity, types[k], num_nodes, std::move(tags[k]), std::move(nodes[k])});
  }
}

// Nodes, and the elements of every entity of `groups` (each entity once).
RawMesh extract(std::vector<RawGroup> groups) {
  RawMesh raw;
  std::vector<double> parametric;
  // Each node once: with includeBoundary, nodes on an entity's boundary come again.
  gmsh::model::mesh::getNodes(raw.node_tags, raw.coords, parametric, -1, -1, false, false);
  std::set<std::pair<int, int>> done;
  for (const auto& g : groups)
    for (int e : g.entities)
      if (done.insert({g.dim, e}).second) add_elements(raw, g.dim, e);
  raw.groups = std::move(groups);
  return raw;
}

// Gmsh's own physical groups, merged by (dimension, name).
std::vector<RawGroup> physical_groups() {
  std::map<std::pair<int, std::string>, std::vector<int>> by_name;
  for (int dim : {1, 2}) {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim);
    for (const auto& [d, tag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(d, tag, name);
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
      auto& all = by_name[{d, name}];
      all.insert(all.end(), entities.begin(), entities.end());
    }
  }
  std::vector<RawGroup> out;
  for (auto& [key, entities] : by_name) out.push_back({key.first, key.second, std::move(entities)});
  return out;
}

// What the parent must see to refuse a file Gmsh repaired silently.
std::vector<std::string> notable_log() {
  std::vector<std::string> all, out;
  gmsh::logger::get(all);
  for (auto& line : all) {
    const bool notable = line.rfind("Warning", 0) == 0 || line.rfind("Error", 0) == 0 ||
                         line.find("Skipping") != std::string::npos;
    if (notable && out.size() < 50) out.push_back(line.substr(0, 300));
  }
  return out;
}

// The script as a file Gmsh can open, seek in (its loops and functions rewind) and name
// in messages, written nowhere: an anonymous memory file, "h = <h>; " put before its
// first line so that line numbers stay the user's.
std::string script_in_memory(const ScriptGeometry& g) {
  const int fd = ::memfd_create("structure.geo", 0);
  if (fd < 0) throw std::string("cannot hold the script in memory");
  char prefix[64];
  std::snprintf(prefix, sizeof prefix, "h = %.17g; ", g.h);
  const std::string text = prefix + g.text;
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t k = ::write(fd, text.data() + done, text.size() - done);
    if (k <= 0) throw std::string("cannot hold the script in memory");
    done += static_cast<std::size_t>(k);
  }
  return "/proc/self/fd/" + std::to_string(fd);
}

// `text` with the memory file's name replaced by the user's path.
std::string in_users_words(std::string text, const std::string& memory_name,
                           const std::string& path) {
  for (auto at = text.find(memory_name); at != std::string::npos;
       at = text.find(memory_name, at + path.size()))
    text.replace(at, memory_name.size(), path);
  return text.substr(0, 400);
}

// The first error Gmsh logged (it logs some without throwing).
void throw_logged_error() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (const std::string& line : log)
    if (line.rfind("Error", 0) == 0) throw line;
}

// A mesh larger than the case allows is refused before it is made: the bounding box's
// area at size h (2.4 triangles per h², as case_checks.cpp counts a rectangle).
void check_script_geometry(const ScriptGeometry& g) {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  std::vector<std::pair<int, int>> surfaces;
  gmsh::model::getEntities(surfaces, 2);
  if (surfaces.empty() || !(x1 > x0 && y1 > y0)) throw std::string("the script defines no surface");
  if (std::abs(z1 - z0) > 1e-9 * std::max(x1 - x0, y1 - y0))
    throw std::string("the geometry leaves the plane z = 0 (z from " + std::to_string(z0) + " to " +
                      std::to_string(z1) + ")");
  const double estimate = 2.4 * (x1 - x0) * (y1 - y0) / (g.h * g.h);
  if (estimate > g.max_triangles)
    throw std::string("its bounding box would need up to " +
                      std::to_string(static_cast<long>(estimate)) +
                      " triangles at structure.h = " + std::to_string(g.h) +
                      ", above the limit of " + std::to_string(static_cast<long>(g.max_triangles)));
}

}  // namespace

RawMesh mesh_script_in_gmsh(const ScriptGeometry& g, void (*fence)()) {
  configure_gmsh(2);
  gmsh::logger::start();
  const std::string name = script_in_memory(g);
  fence();
  try {
    gmsh::open(name);
    throw_logged_error();
    check_script_geometry(g);
    // The case's sizes over the script's: first order triangles at most h.
    gmsh::option::setNumber("Mesh.ElementOrder", 1);
    gmsh::option::setNumber("Mesh.RecombineAll", 0);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
    gmsh::model::mesh::clear();
    mesh_2d(g.h);
    throw_logged_error();
  } catch (const std::string& what) {  // Gmsh 4.8 throws its errors as std::string
    throw in_users_words(what, name, g.path);
  }
  return extract(physical_groups());
}

// Initialising in every child instead cost 6 ms more per call (measured: 8.5 against
// 2.1 ms for fork, set-up and exit), most of it loading locales and rewriting FLTK's
// preference files (/etc/fltk/..., ~/.fltk/...), which Gmsh does on each
// initialisation. It starts no thread and installs no signal handler (measured).
std::string initialise_gmsh() {
  try {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    return "";
  } catch (const std::string& what) {  // Gmsh 4.8 throws its errors as std::string
    return what.empty() ? "Gmsh failed" : what;
  }
}

RawMesh mesh_structure_in_gmsh(const StructureGeometry& g) {
  configure_gmsh(0);
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
  const int surface = geo::addPlaneSurface({loop});
  geo::synchronize();
  mesh_2d(h);
  return extract({{2, "Omega_S", {surface}},
                  {1, "Gamma_D", {left}},
                  {1, "Gamma_C", {contact}},
                  {1, "Gamma_N", {bottom_left, bottom_right, right, top}}});
}

namespace {

// A circle as four arcs, east → north → west → south → east, in the order (and so
// with the tags) the paper's one-disk box always had.
std::vector<int> add_circle(double x0, double y0, double r, double h) {
  namespace geo = gmsh::model::geo;
  const int centre = geo::addPoint(x0, y0, 0, h);
  const int e = geo::addPoint(x0 + r, y0, 0, h), n = geo::addPoint(x0, y0 + r, 0, h),
            w = geo::addPoint(x0 - r, y0, 0, h), s = geo::addPoint(x0, y0 - r, 0, h);
  return {geo::addCircleArc(e, centre, n), geo::addCircleArc(n, centre, w),
          geo::addCircleArc(w, centre, s), geo::addCircleArc(s, centre, e)};
}

// A polygon as a loop of lines through its corners. Each corner's size is at most half
// its shorter side, so that the mesh grades down to a short side; the sides shorter
// than 2h get three nodes outright (the band's size field ignores the points' sizes):
// every side is cut into at least two segments (SPEC §9: a hole of D).
std::vector<int> add_polygon(const std::vector<Point>& corners, double h) {
  namespace geo = gmsh::model::geo;
  const std::size_t m = corners.size();
  auto side = [&](std::size_t i) { return (corners[(i + 1) % m] - corners[i]).norm(); };
  std::vector<int> points, lines;
  for (std::size_t i = 0; i < m; ++i)
    points.push_back(geo::addPoint(corners[i].x(), corners[i].y(), 0,
                                   std::min({h, side(i) / 2, side((i + m - 1) % m) / 2})));
  for (std::size_t i = 0; i < m; ++i) lines.push_back(geo::addLine(points[i], points[(i + 1) % m]));
  return lines;
}

void cut_short_sides(const std::vector<Point>& corners, const std::vector<int>& lines, double h) {
  for (std::size_t i = 0; i < corners.size(); ++i)
    if ((corners[(i + 1) % corners.size()] - corners[i]).norm() < 2 * h)
      gmsh::model::mesh::setTransfiniteCurve(lines[i], 3);
}

// D's holes (FluidGeometry::holes, or the one disk) as Gmsh curves: a circle's four
// arcs, a polygon's sides, in order.
struct HoleCurves {
  std::vector<FluidHole> holes;
  std::vector<std::vector<int>> curves;
};

HoleCurves add_holes(const FluidGeometry& g) {
  HoleCurves out{g.holes ? *g.holes : std::vector<FluidHole>{{g.x0, g.y0, g.r}}, {}};
  for (const FluidHole& hole : out.holes)
    out.curves.push_back(hole.corners.empty() ? add_circle(hole.x0, hole.y0, hole.r, g.h)
                                              : add_polygon(hole.corners, g.h));
  return out;
}

// After synchronising: every polygon side cut into at least two segments.
void cut_short_sides(const HoleCurves& h, double size) {
  for (std::size_t k = 0; k < h.holes.size(); ++k)
    if (!h.holes[k].corners.empty()) cut_short_sides(h.holes[k].corners, h.curves[k], size);
}

// The refinement at the holes (FluidGeometry::h_holes): the distance d to their curves
// (a Distance field sampled at 1/4 of h_holes along them), the size h_holes + 0.2 d up
// to h (a Threshold field). Its tag.
int add_hole_field(const FluidGeometry& g, const HoleCurves& holes) {
  namespace field = gmsh::model::mesh::field;
  std::vector<double> curves;
  double length = 0;
  for (std::size_t k = 0; k < holes.holes.size(); ++k) {
    for (int c : holes.curves[k]) curves.push_back(c);
    length += hole_perimeter(holes.holes[k].r, holes.holes[k].corners);
  }
  const int distance = field::add("Distance");
  field::setNumbers(distance, "CurvesList", curves);
  field::setNumber(distance, "NumPointsPerCurve", std::max(20.0, std::ceil(4 * length / g.h_holes / static_cast<double>(curves.size()))));
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", g.h_holes);
  field::setNumber(threshold, "SizeMax", g.h);
  field::setNumber(threshold, "DistMin", 0);
  field::setNumber(threshold, "DistMax", (g.h - g.h_holes) / kBandGrowth);
  return threshold;
}

// The size fields, if any, as the only size source, so that the corners' sizes h do
// not spread into the refined regions and theirs do not spread along the boundary:
// the band's, the holes', or the smaller of the two (a Min field).
void set_size_fields(const FluidGeometry& g, const HoleCurves& holes) {
  namespace field = gmsh::model::mesh::field;
  std::vector<double> fields;
  if (g.h_near > 0) fields.push_back(add_band_field(g));
  if (g.h_holes > 0) fields.push_back(add_hole_field(g, holes));
  if (fields.empty()) return;
  int size = static_cast<int>(fields[0]);
  if (fields.size() > 1) {
    size = field::add("Min");
    field::setNumbers(size, "FieldsList", fields);
  }
  field::setAsBackgroundMesh(size);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
}

// Σ5, and each hole's own group Sigma_5_k for its force (SPEC §10) when the holes are
// [[obstacles]]'.
void add_hole_groups(const FluidGeometry& g, const HoleCurves& h, std::vector<RawGroup>& groups) {
  std::vector<int> all;
  for (std::size_t k = 0; k < h.curves.size(); ++k) {
    all.insert(all.end(), h.curves[k].begin(), h.curves[k].end());
    if (g.holes) groups.push_back({1, "Sigma_5_" + std::to_string(k + 1), h.curves[k]});
  }
  if (!all.empty()) groups.push_back({1, "Sigma_5", all});
}

}  // namespace

RawMesh mesh_fluid_in_gmsh(const FluidGeometry& g) {
  configure_gmsh(0);
  namespace geo = gmsh::model::geo;
  gmsh::model::add("fluid");
  const double h = g.h;
  const int a = geo::addPoint(0, -g.H2, 0, h), b = geo::addPoint(g.L1, -g.H2, 0, h),
            c = geo::addPoint(g.L1, g.H1, 0, h), d = geo::addPoint(0, g.H1, 0, h);
  const int bottom = geo::addLine(a, b), right = geo::addLine(b, c), top = geo::addLine(c, d),
            left = geo::addLine(d, a);
  const HoleCurves holes = add_holes(g);
  std::vector<int> loops = {geo::addCurveLoop({bottom, right, top, left})};
  for (const auto& curves : holes.curves) loops.push_back(geo::addCurveLoop(curves));
  const int surface = geo::addPlaneSurface(loops);
  geo::synchronize();
  cut_short_sides(holes, h);
  set_size_fields(g, holes);
  mesh_2d(h, g.h_near > 0 || g.h_holes > 0 ? MeshOptions{5, 0} : MeshOptions{});
  std::vector<RawGroup> groups = {{2, "D", {surface}},
                                  {1, "Sigma_1", {left}},
                                  {1, "Sigma_2", {bottom}},
                                  {1, "Sigma_3", {right}},
                                  {1, "Sigma_4", {top}}};
  add_hole_groups(g, holes, groups);
  return extract(std::move(groups));
}

RawMesh mesh_fluid_around_in_gmsh(const BodyFittedGeometry& g) {
  configure_gmsh(0);
  namespace geo = gmsh::model::geo;
  gmsh::model::add("fluid-around-structure");
  const FluidGeometry& box = g.box;
  const double h = box.h;
  const int a = geo::addPoint(0, -box.H2, 0, h), b = geo::addPoint(box.L1, -box.H2, 0, h),
            c = geo::addPoint(box.L1, box.H1, 0, h), d = geo::addPoint(0, box.H1, 0, h);
  std::vector<int> points;  // the outline, from its lower end on x = 0 to its upper end
  for (const Point& p : g.outline) points.push_back(geo::addPoint(p.x(), p.y(), 0, h));
  const int bottom = geo::addLine(a, b), right = geo::addLine(b, c), top = geo::addLine(c, d);
  const int left_above = geo::addLine(d, points.back()),
            left_below = geo::addLine(points.front(), a);
  // The fluid's outer loop runs down Σ1 to the structure, back along its outline and
  // down Σ1 again. One mesh edge per outline segment: no vertex is added on it.
  std::vector<int> outline, loop = {bottom, right, top, left_above};
  for (std::size_t k = points.size() - 1; k > 0; --k) {
    outline.push_back(geo::addLine(points[k], points[k - 1]));
    loop.push_back(outline.back());
  }
  loop.push_back(left_below);
  const HoleCurves holes = add_holes(box);  // [[obstacles]]' holes, or the one disk
  std::vector<int> loops = {geo::addCurveLoop(loop)};
  for (const auto& curves : holes.curves) loops.push_back(geo::addCurveLoop(curves));
  const int surface = geo::addPlaneSurface(loops);
  geo::synchronize();
  for (int line : outline) gmsh::model::mesh::setTransfiniteCurve(line, 2);
  cut_short_sides(holes, h);
  mesh_2d(h);
  std::vector<RawGroup> groups = {{2, "D", {surface}},
                                  {1, "Sigma_1", {left_above, left_below}},
                                  {1, "Sigma_2", {bottom}},
                                  {1, "Sigma_3", {right}},
                                  {1, "Sigma_4", {top}}};
  add_hole_groups(box, holes, groups);
  groups.push_back({1, "Gamma_u", outline});
  return extract(std::move(groups));
}

RawMesh read_in_gmsh(const std::string& path) {
  configure_gmsh(5);  // 5: the "Skipping duplicate node" notes are at the info level
  gmsh::logger::start();
  gmsh::open(path);
  RawMesh raw = extract(physical_groups());
  raw.log = notable_log();
  return raw;
}

}  // namespace fsi

extern "C" __attribute__((visibility("default"))) const fsi::GmshPlugin* fsicontact_gmsh_plugin() {
  static const fsi::GmshPlugin table = {
      fsi::kGmshPluginVersion, fsi::initialise_gmsh,           fsi::mesh_structure_in_gmsh,
      fsi::mesh_fluid_in_gmsh, fsi::mesh_fluid_around_in_gmsh, fsi::mesh_script_in_gmsh,
      fsi::read_in_gmsh};
  return &table;
}
