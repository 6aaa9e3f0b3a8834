// The outputs of a run (issue 15): fluid.vtu in each output.vtu_format, and the
// velocity figure's two costs — painting the field and encoding the PNG — against
// the ways they were done before (Cairo's mesh patterns, Cairo's PNG writer), on the
// §7.2 box at hF = 0.01 and 0.0025 with a smooth field. docs/performance.md
// ("Outputs") gives the numbers.
//   build/bench/output_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/figure.hpp"
#include "io/png.hpp"
#include "io/vtu.hpp"
#include "mesh/generated_mesh.hpp"

namespace fsi {
namespace {

namespace fs = std::filesystem;

const Mesh& box(int inverse_h) {
  static Mesh meshes[2];
  Mesh& m = meshes[inverse_h == 100 ? 0 : 1];
  if (m.triangles.empty())
    m = generate_fluid_mesh({0.41, 0.5, 0.5, 0.2, -0.07, 0.05, 1.0 / inverse_h});
  return m;
}

Eigen::VectorXd field(const Mesh& m) {
  Eigen::VectorXd f(m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v)
    f[v] = 30 * std::exp(-40 * (m.vertices[v] - Point(0.35, -0.03)).squaredNorm()) +
           5 * m.vertices[v].x();
  return f;
}

// (1/hF, 0 binary | 1 zlib | 2 ascii)
void vtu(benchmark::State& state) {
  const Mesh& m = box(static_cast<int>(state.range(0)));
  const VtuFormat format = state.range(1) == 0   ? VtuFormat::binary
                           : state.range(1) == 1 ? VtuFormat::zlib
                                                 : VtuFormat::ascii;
  const Eigen::VectorXd f = field(m), chi = Eigen::VectorXd::Zero(m.num_triangles());
  const fs::path path = fs::temp_directory_path() / "fsicontact-output-bench.vtu";
  for (auto _ : state)
    write_vtu(path, m,
              {vector_field("velocity", f, f), scalar_field("velocity_magnitude", f),
               scalar_field("pressure", f), scalar_field("chi", chi, true)},
              format);
  state.counters["MB"] = static_cast<double>(fs::file_size(path)) / 1e6;
  fs::remove(path);
}
BENCHMARK(vtu)->ArgsProduct({{100, 400}, {0, 1, 2}})->Unit(benchmark::kMillisecond);

// The field painted as before issue 15: a Cairo mesh pattern (Gouraud patch) per
// triangle, flushed every 4096.
void paint_with_cairo_patterns(cairo_t* cr, const Figure& fig, const Mesh& m,
                               const Eigen::VectorXd& f) {
  const double hi = f.maxCoeff();
  cairo_pattern_t* pattern = cairo_pattern_create_mesh();
  int patches = 0;
  for (const auto& t : m.triangles) {
    cairo_mesh_pattern_begin_patch(pattern);
    for (int k = 0; k < 3; ++k) {
      const Point p = fig.pixel(m.vertices[t[k]]);
      (k == 0 ? cairo_mesh_pattern_move_to : cairo_mesh_pattern_line_to)(pattern, p.x(), p.y());
    }
    for (int k = 0; k < 3; ++k) {
      const Rgb c = viridis(f[t[k]] / hi);
      cairo_mesh_pattern_set_corner_color_rgb(pattern, static_cast<unsigned>(k), c[0], c[1], c[2]);
    }
    cairo_mesh_pattern_end_patch(pattern);
    if (++patches == 4096) {
      cairo_set_source(cr, pattern);
      cairo_paint(cr);
      cairo_pattern_destroy(pattern);
      pattern = cairo_pattern_create_mesh();
      patches = 0;
    }
  }
  cairo_set_source(cr, pattern);
  cairo_paint(cr);
  cairo_pattern_destroy(pattern);
}

// (1/hF, 0 painted pixel by pixel (the program) | 1 Cairo's mesh patterns (before))
void paint(benchmark::State& state) {
  const Mesh& m = box(static_cast<int>(state.range(0)));
  const Eigen::VectorXd f = field(m);
  Figure fig({-0.01, 0.42, -0.51, 0.51}, 520, "bench");
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 800, 1400);
  cairo_t* cr = cairo_create(surface);
  for (auto _ : state) {
    if (state.range(1) == 0)
      fig.shade(m, f, 0, f.maxCoeff());
    else
      paint_with_cairo_patterns(cr, fig, m, f);
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}
BENCHMARK(paint)->ArgsProduct({{100, 400}, {0, 1}})->Unit(benchmark::kMillisecond);

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// The figure's PNG: 0 write_png_atomically (libpng, zlib level 1, run-length, "up"
// filter) | 1 Cairo's writer (before).
void png(benchmark::State& state) {
  const Mesh& m = box(100);
  Figure fig({-0.01, 0.42, -0.51, 0.51}, 520, "bench");
  fig.shade(m, field(m), 0, 35);
  const fs::path path = fs::temp_directory_path() / "fsicontact-output-bench.png";
  fig.save_png(path);  // the figure's surface, read back to encode it either way
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  cairo_surface_t* rgb =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, cairo_image_surface_get_width(surface),
                                 cairo_image_surface_get_height(surface));
  cairo_t* cr = cairo_create(rgb);
  cairo_set_source_surface(cr, surface, 0, 0);
  cairo_paint(cr);
  cairo_destroy(cr);
  std::string bytes;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      write_png_atomically(path, rgb);
    } else {
      bytes.clear();
      cairo_surface_write_to_png_stream(rgb, append, &bytes);
    }
  }
  state.counters["kB"] = (state.range(0) == 0 ? static_cast<double>(fs::file_size(path))
                                              : static_cast<double>(bytes.size())) /
                         1e3;
  cairo_surface_destroy(rgb);
  cairo_surface_destroy(surface);
  fs::remove(path);
}
BENCHMARK(png)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
