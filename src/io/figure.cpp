#include "io/figure.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "io/png.hpp"
#include "io/raster.hpp"

namespace fsi {
namespace {

constexpr int kMargin = 70, kBarWidth = 22, kBarSpace = 120, kTitle = 48;
constexpr double kTitleFontSize = 17, kNoteFontSize = 13;  // also what load_figure_fonts loads

std::string tick_label(double v, double step) {
  char text[32];
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  if (std::abs(v) < 1e-3 * step) v = 0;
  if (decimals > 5 || std::abs(v) >= 1e5)
    std::snprintf(text, sizeof text, "%.2g", v);
  else
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

// 1, 2 or 5 × 10^k so that about `count` ticks fit in the range.
double nice_step(double range, int count) {
  const double raw = range / count;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

}  // namespace

Figure::Figure(const WorldBox& box, int width, const std::string& title) : box_(box) {
  if (!(box.x_max > box.x_min && box.y_max > box.y_min)) throw std::logic_error("empty figure box");
  plot_w_ = width;
  scale_ = width / (box.x_max - box.x_min);
  plot_h_ = static_cast<int>(std::ceil(scale_ * (box.y_max - box.y_min)));
  left_ = kMargin + 20;
  top_ = kTitle + 30;
  width_ = left_ + plot_w_ + kBarSpace + 40;
  height_ = top_ + plot_h_ + kMargin;
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_, height_);
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr_, kTitleFontSize);
  cairo_set_source_rgb(cr_, 0, 0, 0);
  cairo_move_to(cr_, left_, 28);
  cairo_show_text(cr_, title.c_str());
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
}

void load_figure_fonts() {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  cairo_t* cr = cairo_create(surface);
  cairo_text_extents_t extents;
  for (const auto weight : {CAIRO_FONT_WEIGHT_BOLD, CAIRO_FONT_WEIGHT_NORMAL}) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, weight);
    cairo_set_font_size(cr, weight == CAIRO_FONT_WEIGHT_BOLD ? kTitleFontSize : kNoteFontSize);
    cairo_text_extents(cr, "0", &extents);
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

Figure::~Figure() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

double Figure::px(double x) const { return left_ + (x - box_.x_min) * scale_; }
double Figure::py(double y) const { return top_ + (box_.y_max - y) * scale_; }

void Figure::note(const std::string& text) {
  cairo_set_font_size(cr_, kNoteFontSize);
  cairo_set_source_rgb(cr_, 0.25, 0.25, 0.25);
  cairo_move_to(cr_, left_, 48 + 17 * notes_++);
  cairo_show_text(cr_, text.c_str());
}

void Figure::shade(const Mesh& mesh, const Eigen::VectorXd& value, double lo, double hi) {
  const double span = hi > lo ? hi - lo : 1.0;
  std::vector<Point> at(mesh.vertices.size());
  std::vector<double> t01(mesh.vertices.size());
  for (std::size_t v = 0; v < at.size(); ++v) {
    at[v] = pixel(mesh.vertices[v]);
    t01[v] = std::isfinite(value[v]) ? (value[v] - lo) / span : 0.0;
  }
  cairo_surface_flush(surface_);
  paint_field({reinterpret_cast<std::uint32_t*>(cairo_image_surface_get_data(surface_)),
               cairo_image_surface_get_stride(surface_),
               {left_, top_, left_ + plot_w_, top_ + plot_h_}},
              at, mesh.triangles, t01);
  cairo_surface_mark_dirty(surface_);
}

void Figure::fill_cells(const Mesh& mesh, const Eigen::VectorXd& value, double lo, double hi) {
  const double span = hi > lo ? hi - lo : 1.0;
  cairo_save(cr_);
  cairo_rectangle(cr_, left_, top_, plot_w_, plot_h_);
  cairo_clip(cr_);
  cairo_set_line_width(cr_, 0.6);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Point& p = mesh.vertices[tri[k]];
      (k == 0 ? cairo_move_to : cairo_line_to)(cr_, px(p.x()), py(p.y()));
    }
    cairo_close_path(cr_);
    const Rgb c = viridis((value[t] - lo) / span);
    cairo_set_source_rgb(cr_, c[0], c[1], c[2]);
    cairo_fill_preserve(cr_);
    cairo_stroke(cr_);  // hides hairline seams between cells
  }
  cairo_restore(cr_);
}

void Figure::polyline(const std::vector<Point>& points, const Rgb& colour, double width_px,
                      bool closed, bool dashed) {
  if (points.size() < 2) return;
  cairo_save(cr_);
  cairo_rectangle(cr_, left_, top_, plot_w_, plot_h_);
  cairo_clip(cr_);
  cairo_move_to(cr_, px(points[0].x()), py(points[0].y()));
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, px(points[i].x()), py(points[i].y()));
  if (closed) cairo_close_path(cr_);
  if (dashed) {
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr_, dash, 2, 0);
  }
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_source_rgb(cr_, colour[0], colour[1], colour[2]);
  cairo_set_line_width(cr_, width_px);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Figure::filled_polygon(const std::vector<Point>& points, const Rgb& colour, double alpha) {
  if (points.size() < 3) return;
  cairo_save(cr_);
  cairo_rectangle(cr_, left_, top_, plot_w_, plot_h_);
  cairo_clip(cr_);
  cairo_move_to(cr_, px(points[0].x()), py(points[0].y()));
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, px(points[i].x()), py(points[i].y()));
  cairo_close_path(cr_);
  cairo_set_source_rgba(cr_, colour[0], colour[1], colour[2], alpha);
  cairo_fill(cr_);
  cairo_restore(cr_);
}

void Figure::arrow(const Point& tail, const Point& head, const Rgb& colour, double width_px) {
  const double x0 = px(tail.x()), y0 = py(tail.y()), x1 = px(head.x()), y1 = py(head.y());
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (!(length > 1.0)) return;  // under a pixel: nothing to see
  const double ux = (x1 - x0) / length, uy = (y1 - y0) / length, tip = std::min(0.35 * length, 4.0 * width_px + 3.0);
  cairo_save(cr_);
  cairo_rectangle(cr_, left_, top_, plot_w_, plot_h_);
  cairo_clip(cr_);
  cairo_set_source_rgb(cr_, colour[0], colour[1], colour[2]);
  cairo_set_line_width(cr_, width_px);
  cairo_move_to(cr_, x0, y0);
  cairo_line_to(cr_, x1 - ux * tip, y1 - uy * tip);
  cairo_stroke(cr_);
  cairo_move_to(cr_, x1, y1);  // the head: a triangle of half-width tip/2
  cairo_line_to(cr_, x1 - ux * tip - uy * tip / 2, y1 - uy * tip + ux * tip / 2);
  cairo_line_to(cr_, x1 - ux * tip + uy * tip / 2, y1 - uy * tip - ux * tip / 2);
  cairo_close_path(cr_);
  cairo_fill(cr_);
  cairo_restore(cr_);
}

void Figure::marker(const Point& p, const Rgb& colour, double radius_px) {
  cairo_save(cr_);
  cairo_arc(cr_, px(p.x()), py(p.y()), radius_px, 0, 2 * M_PI);
  cairo_set_source_rgb(cr_, colour[0], colour[1], colour[2]);
  cairo_fill(cr_);
  cairo_restore(cr_);
}

void Figure::colour_bar(double lo, double hi, const std::string& label) {
  const double x = left_ + plot_w_ + 30, y0 = top_, h = plot_h_;
  for (int i = 0; i < static_cast<int>(h); ++i) {
    const Rgb c = viridis(1.0 - i / h);
    cairo_set_source_rgb(cr_, c[0], c[1], c[2]);
    cairo_rectangle(cr_, x, y0 + i, kBarWidth, 1.2);
    cairo_fill(cr_);
  }
  cairo_set_source_rgb(cr_, 0, 0, 0);
  cairo_set_line_width(cr_, 1);
  cairo_rectangle(cr_, x, y0, kBarWidth, h);
  cairo_stroke(cr_);
  cairo_set_font_size(cr_, 12);
  const double span = hi > lo ? hi - lo : 1.0;
  const double step = nice_step(span, std::max(2, static_cast<int>(h / 60)));
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) {
    const double yy = y0 + h * (1 - (v - lo) / span);
    cairo_move_to(cr_, x + kBarWidth, yy);
    cairo_line_to(cr_, x + kBarWidth + 5, yy);
    cairo_stroke(cr_);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    cairo_move_to(cr_, x + kBarWidth + 8, yy + 4);
    cairo_show_text(cr_, text);
  }
  cairo_move_to(cr_, x - 4, y0 - 10);
  cairo_show_text(cr_, label.c_str());
}

void Figure::legend(const std::vector<std::pair<Rgb, std::string>>& entries) {
  cairo_set_font_size(cr_, 12);
  double x = left_;
  const double y = top_ + plot_h_ + 52;
  for (const auto& [c, text] : entries) {
    cairo_set_source_rgb(cr_, c[0], c[1], c[2]);
    cairo_rectangle(cr_, x, y - 9, 16, 10);
    cairo_fill_preserve(cr_);
    cairo_set_source_rgb(cr_, 0, 0, 0);
    cairo_set_line_width(cr_, 0.8);
    cairo_stroke(cr_);
    cairo_move_to(cr_, x + 22, y);
    cairo_show_text(cr_, text.c_str());
    cairo_text_extents_t ext;
    cairo_text_extents(cr_, text.c_str(), &ext);
    x += 40 + ext.x_advance;
  }
}

void Figure::axes(const std::string& x_label, const std::string& y_label) {
  cairo_set_source_rgb(cr_, 0, 0, 0);
  cairo_set_line_width(cr_, 1);
  cairo_rectangle(cr_, left_, top_, plot_w_, plot_h_);
  cairo_stroke(cr_);
  cairo_set_font_size(cr_, 12);
  const double sx = nice_step(box_.x_max - box_.x_min, std::max(2, plot_w_ / 110));
  for (double v = std::ceil(box_.x_min / sx) * sx; v <= box_.x_max + 1e-9 * sx; v += sx) {
    cairo_move_to(cr_, px(v), top_ + plot_h_);
    cairo_line_to(cr_, px(v), top_ + plot_h_ + 5);
    cairo_stroke(cr_);
    const std::string t = tick_label(v, sx);
    cairo_text_extents_t ext;
    cairo_text_extents(cr_, t.c_str(), &ext);
    cairo_move_to(cr_, px(v) - ext.width / 2, top_ + plot_h_ + 19);
    cairo_show_text(cr_, t.c_str());
  }
  const double sy = nice_step(box_.y_max - box_.y_min, std::max(2, plot_h_ / 70));
  for (double v = std::ceil(box_.y_min / sy) * sy; v <= box_.y_max + 1e-9 * sy; v += sy) {
    cairo_move_to(cr_, left_ - 5, py(v));
    cairo_line_to(cr_, left_, py(v));
    cairo_stroke(cr_);
    const std::string t = tick_label(v, sy);
    cairo_text_extents_t ext;
    cairo_text_extents(cr_, t.c_str(), &ext);
    cairo_move_to(cr_, left_ - 8 - ext.width, py(v) + 4);
    cairo_show_text(cr_, t.c_str());
  }
  cairo_move_to(cr_, left_ + plot_w_ / 2.0 - 20, top_ + plot_h_ + 36);
  cairo_show_text(cr_, x_label.c_str());
  cairo_save(cr_);
  cairo_move_to(cr_, 18, top_ + plot_h_ / 2.0 + 20);
  cairo_rotate(cr_, -M_PI / 2);
  cairo_show_text(cr_, y_label.c_str());
  cairo_restore(cr_);
}

void Figure::save_png(const std::string& path) {
  write_png_atomically(path, surface_);
}

std::string Figure::png(const std::string& name) const { return encode_png(surface_, name); }

std::vector<std::vector<Point>> boundary_loops(const Mesh& mesh) {
  // Boundary edges are the triangle edges used once; chain them into loops.
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::map<int, int> next;  // counter-clockwise successor along the boundary
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (count[{std::min(a, b), std::max(a, b)}] == 1) next[a] = b;
    }
  std::vector<std::vector<Point>> loops;
  while (!next.empty()) {
    std::vector<Point> loop;
    int v = next.begin()->first;
    while (next.count(v)) {
      loop.push_back(mesh.vertices[v]);
      const int w = next[v];
      next.erase(v);
      v = w;
    }
    loops.push_back(loop);
  }
  return loops;
}

}  // namespace fsi
