#include "io/chart.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

#include "io/png.hpp"

namespace fsi {
namespace {

constexpr int kLeft = 90, kRight = 30, kTop = 60, kBottom = 70;

struct Axis {
  double lo, hi;
  bool log;
  double map(double v, double p0, double p1) const {
    const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
    return p0 + t * (p1 - p0);
  }
  std::vector<double> ticks() const {
    std::vector<double> t;
    if (log) {
      for (double e = std::floor(std::log10(lo)); e <= std::ceil(std::log10(hi)); ++e) {
        const double v = std::pow(10.0, e);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
      }
      return t;
    }
    const double raw = (hi - lo) / 6, p = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * p;
    for (double m : {1.0, 2.0, 5.0})
      if (m * p >= raw) {
        step = m * p;
        break;
      }
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) t.push_back(v);
    return t;
  }
};

Axis axis_of(const std::vector<Series>& series, bool x, bool log) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series)
    for (double v : x ? s.x : s.y)
      if (std::isfinite(v) && (!log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(hi >= lo)) lo = 1, hi = 10;
  if (log) {
    lo = std::pow(10.0, std::floor(std::log10(lo) * 4) / 4);
    hi = std::pow(10.0, std::ceil(std::log10(hi) * 4) / 4);
    if (hi <= lo) hi = lo * 10;
  } else {
    const double pad = 0.05 * (hi > lo ? hi - lo : std::abs(hi) + 1);
    lo -= pad, hi += pad;
  }
  return {lo, hi, log};
}

std::string label_of(double v) {
  char t[32];
  std::snprintf(t, sizeof t, "%g", v);
  return t;
}

// The plot area in pixels: x0 left, x1 right, y0 bottom, y1 top.
struct PlotArea {
  double x0, x1, y0, y1;
};

void draw_background_and_title(cairo_t* cr, const ChartOptions& o, const PlotArea& a) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 16);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, a.x0, 30);
  cairo_show_text(cr, o.title.c_str());
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
}

void draw_x_grid_and_ticks(cairo_t* cr, const Axis& ax, const PlotArea& a) {
  for (double v : ax.ticks()) {
    const double px = ax.map(v, a.x0, a.x1);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px, a.y0);
    cairo_line_to(cr, px, a.y1);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::string t = label_of(v);
    cairo_text_extents_t e;
    cairo_text_extents(cr, t.c_str(), &e);
    cairo_move_to(cr, px - e.width / 2, a.y0 + 18);
    cairo_show_text(cr, t.c_str());
  }
}

void draw_y_grid_and_ticks(cairo_t* cr, const Axis& ay, const PlotArea& a) {
  for (double v : ay.ticks()) {
    const double py = ay.map(v, a.y0, a.y1);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, a.x0, py);
    cairo_line_to(cr, a.x1, py);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::string t = label_of(v);
    cairo_text_extents_t e;
    cairo_text_extents(cr, t.c_str(), &e);
    cairo_move_to(cr, a.x0 - 8 - e.width, py + 4);
    cairo_show_text(cr, t.c_str());
  }
}

void draw_frame_and_axis_labels(cairo_t* cr, const ChartOptions& o, const PlotArea& a) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, a.x0, a.y1, a.x1 - a.x0, a.y0 - a.y1);
  cairo_stroke(cr);
  cairo_move_to(cr, (a.x0 + a.x1) / 2 - 60, o.height - 25);
  cairo_show_text(cr, o.x_label.c_str());
  cairo_save(cr);
  cairo_move_to(cr, 22, (a.y0 + a.y1) / 2 + 60);
  cairo_rotate(cr, -M_PI / 2);
  cairo_show_text(cr, o.y_label.c_str());
  cairo_restore(cr);
}

// Non-finite points are skipped, and non-positive ones on a log axis.
bool skipped_point(const Series& s, std::size_t i, const Axis& ax, const Axis& ay) {
  return !std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || (ax.log && s.x[i] <= 0) || (ay.log && s.y[i] <= 0);
}

void draw_series_line(cairo_t* cr, const Series& s, const Axis& ax, const Axis& ay, const PlotArea& a) {
  bool started = false;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (skipped_point(s, i, ax, ay)) continue;
    const double px = ax.map(s.x[i], a.x0, a.x1), py = ay.map(s.y[i], a.y0, a.y1);
    if (s.line) {
      if (started) cairo_line_to(cr, px, py);
      else cairo_move_to(cr, px, py), started = true;
    }
  }
  if (s.line) cairo_stroke(cr);
}

void draw_series_markers(cairo_t* cr, const Series& s, const Axis& ax, const Axis& ay, const PlotArea& a) {
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (skipped_point(s, i, ax, ay)) continue;
    cairo_arc(cr, ax.map(s.x[i], a.x0, a.x1), ay.map(s.y[i], a.y0, a.y1), 4, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

// Series, clipped to the plot area.
void draw_series(cairo_t* cr, const std::vector<Series>& series, const Axis& ax, const Axis& ay,
                 const PlotArea& a) {
  cairo_save(cr);
  cairo_rectangle(cr, a.x0, a.y1, a.x1 - a.x0, a.y0 - a.y1);
  cairo_clip(cr);
  for (const auto& s : series) {
    cairo_set_source_rgb(cr, s.colour[0], s.colour[1], s.colour[2]);
    cairo_set_line_width(cr, 2);
    if (s.dashed) {
      const double dash[] = {7.0, 5.0};
      cairo_set_dash(cr, dash, 2, 0);
    } else {
      cairo_set_dash(cr, nullptr, 0, 0);
    }
    draw_series_line(cr, s, ax, ay, a);
    cairo_set_dash(cr, nullptr, 0, 0);
    if (s.markers) draw_series_markers(cr, s, ax, ay, a);
  }
  cairo_restore(cr);
}

// Legend, top left inside the plot.
void draw_legend(cairo_t* cr, const std::vector<Series>& series, const PlotArea& a) {
  double ly = a.y1 + 20;
  for (const auto& s : series) {
    cairo_set_source_rgb(cr, s.colour[0], s.colour[1], s.colour[2]);
    cairo_set_line_width(cr, 2);
    if (s.dashed) {
      const double dash[] = {7.0, 5.0};
      cairo_set_dash(cr, dash, 2, 0);
    }
    cairo_move_to(cr, a.x0 + 12, ly - 4);
    cairo_line_to(cr, a.x0 + 40, ly - 4);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, a.x0 + 48, ly);
    cairo_show_text(cr, s.label.c_str());
    ly += 18;
  }
}

}  // namespace

void write_chart(const std::string& path, const ChartOptions& o, const std::vector<Series>& series) {
  const Axis ax = axis_of(series, true, o.log_x), ay = axis_of(series, false, o.log_y);
  // Owned by RAII handles: the PNG write may throw.
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_owner(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, o.width, o.height), cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_owner(cairo_create(surface_owner.get()), cairo_destroy);
  cairo_surface_t* surface = surface_owner.get();
  cairo_t* cr = cr_owner.get();
  const PlotArea area{kLeft, static_cast<double>(o.width - kRight), static_cast<double>(o.height - kBottom), kTop};
  draw_background_and_title(cr, o, area);
  // Grid and ticks.
  cairo_set_line_width(cr, 1);
  draw_x_grid_and_ticks(cr, ax, area);
  draw_y_grid_and_ticks(cr, ay, area);
  draw_frame_and_axis_labels(cr, o, area);
  draw_series(cr, series, ax, ay, area);
  draw_legend(cr, series, area);
  write_png_atomically(path, surface);
}

}  // namespace fsi
