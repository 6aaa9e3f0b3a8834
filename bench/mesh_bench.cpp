// Meshing the paper's §7.2 box (SPEC §7.2; issues 12 and 15): Gmsh's 2D algorithms on
// the same geometry in this process (1 MeshAdapt, 5 Delaunay, 6 Frontal-Delaunay),
// CGAL's Delaunay refinement alone (from the boundary, no lattice), and the
// program's whole paths generate_fluid_mesh with the lattice generator (the default)
// and with Gmsh (a forked child, the transfer, build and validation), uniform and
// with the band refinement of fluid.h_near. Each reports triangles, µs a triangle
// and the smallest angle. docs/performance.md ("Meshing") gives the numbers.
//   build/bench/mesh_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <gmsh.h>

#include <chrono>
#include <map>
#include <utility>

#include "mesh/constrained_delaunay.hpp"
#include "mesh/generated_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/planar_domain.hpp"

namespace fsi {
namespace {

// The geometry of mesh_fluid_in_gmsh (src/mesh/gmsh_plugin.cpp), meshed with `algorithm`.
std::size_t gmsh_box(int algorithm, double h, int smoothing, double h_near) {
  namespace geo = gmsh::model::geo;
  gmsh::clear();
  gmsh::model::add("box");
  const int a = geo::addPoint(0, -0.5, 0, h), b = geo::addPoint(0.41, -0.5, 0, h), c = geo::addPoint(0.41, 0.5, 0, h),
            d = geo::addPoint(0, 0.5, 0, h);
  const int o = geo::addPoint(0.2, -0.07, 0, h);
  const int e = geo::addPoint(0.25, -0.07, 0, h), n = geo::addPoint(0.2, -0.02, 0, h),
            w = geo::addPoint(0.15, -0.07, 0, h), s = geo::addPoint(0.2, -0.12, 0, h);
  const int outer = geo::addCurveLoop({geo::addLine(a, b), geo::addLine(b, c), geo::addLine(c, d), geo::addLine(d, a)});
  const int hole = geo::addCurveLoop({geo::addCircleArc(e, o, n), geo::addCircleArc(n, o, w),
                                      geo::addCircleArc(w, o, s), geo::addCircleArc(s, o, e)});
  geo::addPlaneSurface({outer, hole});
  geo::synchronize();
  if (h_near > 0) {  // add_band_field's Box field (src/mesh/gmsh_plugin.cpp)
    namespace field = gmsh::model::mesh::field;
    const int box = field::add("Box");
    const std::pair<const char*, double> values[] = {{"VIn", h_near}, {"VOut", h},   {"XMin", 0},  {"YMin", -0.06},
                                                     {"XMax", 0.33},  {"YMax", 0.05}, {"ZMin", -1}, {"ZMax", 1},
                                                     {"Thickness", (h - h_near) / kBandGrowth}};
    for (const auto& [name, value] : values) field::setNumber(box, name, value);
    field::setAsBackgroundMesh(box);
  }
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", h_near > 0 ? 0 : 1);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", h_near > 0 ? 0 : 1);
  gmsh::option::setNumber("Mesh.Algorithm", algorithm);
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.Smoothing", smoothing);
  gmsh::model::mesh::generate(2);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2);
  // This process's Gmsh is the one the program's plugin uses too (one libgmsh): leave
  // the options as the program expects them (measured: the band's settings left behind
  // changed generate_fluid's Gmsh meshes).
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 1);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  return tags.empty() ? 0 : tags[0].size();
}

// The smallest angle of Gmsh's current 2D mesh, in degrees.
double gmsh_min_angle() {
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(node_tags, xyz, parametric, -1, -1, true, false);
  Mesh m;
  std::map<std::size_t, int> index;
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    if (index.emplace(node_tags[i], m.num_vertices()).second)
      m.vertices.emplace_back(xyz[3 * i], xyz[3 * i + 1]);
  }
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2);
  for (std::size_t k = 0; k + 2 < nodes[0].size(); k += 3)
    m.triangles.push_back({index[nodes[0][k]], index[nodes[0][k + 1]], index[nodes[0][k + 2]]});
  return statistics(m).min_angle_deg;
}

void gmsh_algorithm(benchmark::State& state) {
  static bool initialised = false;
  if (!initialised) gmsh::initialize(0, nullptr, false), initialised = true;
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  const int algorithm = static_cast<int>(state.range(0));
  const double h = 1.0 / static_cast<double>(state.range(1));
  const double h_near = state.range(3) > 0 ? 1.0 / static_cast<double>(state.range(3)) : 0.0;
  std::size_t triangles = 0;
  double seconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    triangles = gmsh_box(algorithm, h, static_cast<int>(state.range(2)), h_near);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["us_per_triangle"] = 1e6 * seconds / static_cast<double>(state.iterations()) / static_cast<double>(triangles);
  state.counters["min_angle"] = gmsh_min_angle();
}
// (algorithm, 1/h, smoothing passes, 1/h_near or 0 for a uniform mesh)
BENCHMARK(gmsh_algorithm)
    ->ArgsProduct({{1, 5, 6}, {100, 200, 400}, {1}, {0}})
    ->ArgsProduct({{5, 6}, {400}, {0}, {0}})
    ->ArgsProduct({{5, 6}, {100}, {0, 1}, {1000, 2000}})
    ->Unit(benchmark::kMillisecond);

// CGAL's 2D mesher alone (Delaunay refinement, angles ≥ 20.7°, edges ≤ 1.4 h as the
// lattice generator asks of it), from the box's boundary cut at h: what the generator
// would cost without its lattice.
void cgal_refinement(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  PlanarDomain d{{}, {"box", "disk"}};
  d.loops.push_back({{{0, -0.5}, {0.41, -0.5}},
                     {{0.41, -0.5}, {0.41, 0.5}},
                     {{0.41, 0.5}, {0, 0.5}},
                     {{0, 0.5}, {0, -0.5}}});
  BoundaryPiece disk;
  disk.c = Point(0.2, -0.07), disk.r = 0.05, disk.label = 1;
  d.loops.push_back({disk});
  const BoundarySegments b = cut_boundary(d, SizeField{h});
  Mesh m;
  double seconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    DelaunayMesh dm = constrained_delaunay({b.points, b.segments, {}}, SizeField{h}, 1.4);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.vertices = std::move(dm.vertices), m.triangles = std::move(dm.triangles);
  }
  state.counters["triangles"] = m.num_triangles();
  state.counters["us_per_triangle"] =
      1e6 * seconds / static_cast<double>(state.iterations()) / m.num_triangles();
  state.counters["min_angle"] = statistics(m).min_angle_deg;
}
BENCHMARK(cgal_refinement)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond);

// The program's paths: generate_fluid_mesh with the lattice generator (in process)
// and with Gmsh (fork, Gmsh, transfer, build_mesh, orient_and_validate).
void generate_fluid(benchmark::State& state) {
  FluidGeometry g{0.41, 0.5, 0.5, 0.2, -0.07, 0.05, 1.0 / static_cast<double>(state.range(0))};
  if (state.range(1) > 0) g.h_near = 1.0 / static_cast<double>(state.range(1)), g.band = {0, -0.06, 0.33, 0.05};
  const MeshGenerator by = state.range(2) ? MeshGenerator::gmsh : MeshGenerator::lattice;
  Mesh m;
  double seconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    m = generate_fluid_mesh(g, by);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  state.counters["triangles"] = m.num_triangles();
  state.counters["us_per_triangle"] =
      1e6 * seconds / static_cast<double>(state.iterations()) / m.num_triangles();
  state.counters["min_angle"] = statistics(m).min_angle_deg;
}
// (1/hF, 1/h_near or 0, 0 lattice | 1 Gmsh)
BENCHMARK(generate_fluid)
    ->ArgsProduct({{100, 400, 800}, {0}, {0, 1}})
    ->ArgsProduct({{100}, {1000, 2000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
