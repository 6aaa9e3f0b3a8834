// Meshing the paper's §7.2 box (SPEC §7.2; issue 12's meshing target): Gmsh's 2D
// algorithms on the same geometry in this process (1 MeshAdapt, 5 Delaunay, 6
// Frontal-Delaunay, the program's choice), and the program's whole path
// generate_fluid_mesh (a forked child, the transfer, build and validation), uniform
// and with the band refinement of fluid.h_near. docs/performance.md gives the numbers.
//   build/bench/mesh_bench --benchmark_filter='gmsh_algorithm/.*' --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <gmsh.h>

#include <chrono>
#include <utility>

#include "mesh/gmsh_io.hpp"

namespace fsi {
namespace {

// The geometry of mesh_fluid_in_gmsh (src/mesh/gmsh_model.cpp), meshed with `algorithm`.
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
  if (h_near > 0) {  // add_band_field's Box field (src/mesh/gmsh_model.cpp)
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
  return tags.empty() ? 0 : tags[0].size();
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
}
// (algorithm, 1/h, smoothing passes, 1/h_near or 0 for a uniform mesh)
BENCHMARK(gmsh_algorithm)
    ->ArgsProduct({{1, 5, 6}, {100, 200, 400}, {1}, {0}})
    ->ArgsProduct({{5, 6}, {400}, {0}, {0}})
    ->ArgsProduct({{5, 6}, {100}, {0, 1}, {1000, 2000}})
    ->Unit(benchmark::kMillisecond);

// The program's path: fork, Gmsh, transfer, build_mesh, orient_and_validate.
void generate_fluid(benchmark::State& state) {
  FluidGeometry g{0.41, 0.5, 0.5, 0.2, -0.07, 0.05, 1.0 / static_cast<double>(state.range(0))};
  if (state.range(1) > 0) g.h_near = 1.0 / static_cast<double>(state.range(1)), g.band = {0, -0.06, 0.33, 0.05};
  int triangles = 0;
  double seconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    triangles = generate_fluid_mesh(g).num_triangles();
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  state.counters["triangles"] = triangles;
  state.counters["us_per_triangle"] = 1e6 * seconds / static_cast<double>(state.iterations()) / triangles;
}
// (1/hF, 1/h_near or 0)
BENCHMARK(generate_fluid)->Args({400, 0})->Args({100, 1000})->Args({100, 2000})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
