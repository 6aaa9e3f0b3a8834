// A small plotting canvas over Cairo: world coordinates with equal aspect ratio,
// P1 fields shaded per vertex, outlines, axes with ticks, a colour bar, PNG output.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "io/colour.hpp"  // Rgb, viridis
#include "mesh/mesh.hpp"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace fsi {

struct WorldBox {
  double x_min, x_max, y_min, y_max;
};

// Loads what a figure's first text needs (fontconfig's configuration and font list,
// the FreeType faces of the title and the notes): ~10 ms once per process, which a
// run spends on its second core while it meshes and solves (PenalisedProblem::set_up,
// run/penalised_problem.cpp) instead of in its first figure. Harmless to call more
// than once or from any thread.
void load_figure_fonts();

class Figure {
 public:
  // `width` pixels for the plot area; the height follows from the box (equal aspect).
  Figure(const WorldBox& box, int width, const std::string& title);
  ~Figure();
  Figure(const Figure&) = delete;
  Figure& operator=(const Figure&) = delete;

  // Field `value` per vertex of `mesh`, colour-mapped on [lo, hi], linearly shaded.
  void shade(const Mesh& mesh, const Eigen::VectorXd& value, double lo, double hi);
  // Same with one value per triangle.
  void fill_cells(const Mesh& mesh, const Eigen::VectorXd& value, double lo, double hi);
  void polyline(const std::vector<Point>& points, const Rgb& colour, double width_px,
                bool closed = false, bool dashed = false);
  void filled_polygon(const std::vector<Point>& points, const Rgb& colour, double alpha = 1.0);
  void marker(const Point& p, const Rgb& colour, double radius_px);
  // An arrow from tail to head (world coordinates), its head a few line widths long.
  void arrow(const Point& tail, const Point& head, const Rgb& colour, double width_px);
  void colour_bar(double lo, double hi, const std::string& label);
  void legend(const std::vector<std::pair<Rgb, std::string>>& entries);
  void axes(const std::string& x_label, const std::string& y_label);
  void note(const std::string& text);  // a line under the title
  void save_png(const std::string& path);
  std::string png(const std::string& name) const;  // the PNG's bytes (name: for messages)
  // Where a world point is drawn, in pixels of the saved image (x right, y down): the
  // layout depends on the box and the width only (tests check figures by it).
  Point pixel(const Point& world) const { return Point(px(world.x()), py(world.y())); }

 private:
  double px(double x) const;
  double py(double y) const;

  WorldBox box_;
  double scale_;
  int plot_w_, plot_h_, left_, top_, width_, height_;
  int notes_ = 0;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

// Boundary of a mesh as closed polylines (one per boundary loop).
std::vector<std::vector<Point>> boundary_loops(const Mesh& mesh);

}  // namespace fsi
