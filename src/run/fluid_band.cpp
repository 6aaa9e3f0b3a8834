#include "run/fluid_band.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "qp/qp_problem.hpp"

namespace fsi {
namespace {

// [x_min, y_min, x_max, y_max] of the vertices, displaced by u (2nv, paper ordering).
std::array<double, 4> bounding_box(const Mesh& mesh, const Eigen::VectorXd* u) {
  std::array<double, 4> b = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  const int nv = mesh.num_vertices();
  for (int i = 0; i < nv; ++i) {
    Point x = mesh.vertices[i];
    if (u) x += Point((*u)[i], (*u)[nv + i]);
    b[0] = std::min(b[0], x.x()), b[1] = std::min(b[1], x.y());
    b[2] = std::max(b[2], x.x()), b[3] = std::max(b[3], x.y());
  }
  return b;
}

}  // namespace

bool band_needs_structure(const Case& c) { return c.fluid && c.fluid->h_near > 0 && !c.fluid->band_box; }

std::optional<std::array<double, 4>> fluid_band_box(const Case& c, StructureSetup* s) {
  const FluidParams& f = *c.fluid;
  if (!(f.h_near > 0)) return std::nullopt;
  std::array<double, 4> band;
  if (f.band_box) {
    band = *f.band_box;
  } else {
    Eigen::VectorXd u;
    try {
      u = s->load_alone().u;
    } catch (const QpError& e) {
      throw SolverFailure(std::string("the load-alone contact solution for fluid.band failed: ") + e.what());
    }
    if (!u.allFinite()) throw SolverFailure("the load-alone contact solution for fluid.band is not finite");
    const std::array<double, 4> rest = bounding_box(s->mesh(), nullptr), loaded = bounding_box(s->mesh(), &u);
    band = {std::min(rest[0], loaded[0]) - f.band, std::min(rest[1], loaded[1]) - f.band,
            std::max(rest[2], loaded[2]) + f.band, std::max(rest[3], loaded[3]) + f.band};
  }
  band[0] = std::max(band[0], 0.0), band[1] = std::max(band[1], -f.H2);
  band[2] = std::min(band[2], f.L1), band[3] = std::min(band[3], f.H1);
  return band;
}

bool inside_band(const Mesh& deformed, const std::array<double, 4>& band, double margin) {
  const std::array<double, 4> b = bounding_box(deformed, nullptr);
  // The clamped side lies on Σ1 (x = 0): a band reaching it needs no margin there.
  return (band[0] <= 0 || b[0] >= band[0] + margin) && b[1] >= band[1] + margin &&
         b[2] <= band[2] - margin && b[3] <= band[3] - margin;
}

}  // namespace fsi
