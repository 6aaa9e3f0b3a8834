#include "mesh/planar_domain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/mesh_error.hpp"
#include "mesh/polygon.hpp"

namespace fsi {

double BoundaryPiece::length() const {
  return circle() ? 2 * std::numbers::pi * r : (b - a).norm();
}

Point BoundaryPiece::at(double t) const {
  if (!circle()) return a + t * (b - a);
  const double angle = 2 * std::numbers::pi * t;
  return c + r * Point(std::cos(angle), std::sin(angle));
}

double SizeField::distance_to_band(const Point& x) const {
  const double dx = std::max({band[0] - x.x(), 0.0, x.x() - band[2]});
  const double dy = std::max({band[1] - x.y(), 0.0, x.y() - band[3]});
  return std::hypot(dx, dy);
}

double SizeField::operator()(const Point& x) const {
  if (uniform()) return h;
  return std::min(h, h_near + growth * distance_to_band(x));
}

double distance_to_piece(const BoundaryPiece& piece, const Point& x) {
  if (piece.circle()) return std::abs((x - piece.c).norm() - piece.r);
  return distance_to_segment(x, piece.a, piece.b);
}

namespace {

// The parameters t_0 = 0 < t_1 < ... < t_{n-1} of a piece's points: equal steps of
// ∫ ds / h(x(s)), n the integral rounded up (so no segment is longer than h, up to
// the quadrature of the integral); t = k / n exactly where h is uniform.
std::vector<double> parameters(const BoundaryPiece& piece, const SizeField& size) {
  const double length = piece.length();
  if (!(length > 0) || !std::isfinite(length)) throw MeshError("a boundary piece has no length");
  std::vector<double> t;
  if (size.uniform()) {
    const double n = std::max<double>(piece.min_segments, std::ceil(length / size.h - 1e-9));
    if (n > 1e8) throw MeshError("a boundary piece would need more than 1e8 segments");
    for (int k = 0; k < static_cast<int>(n); ++k) t.push_back(k / n);
    return t;
  }
  // The midpoint rule on m cells, each far smaller than the smallest size.
  const double h_min = std::min(size.h, size.h_near);
  const int m = static_cast<int>(std::clamp(8 * std::ceil(length / h_min), 16.0, 4e6));
  std::vector<double> integral(m + 1, 0.0);
  for (int i = 0; i < m; ++i)
    integral[i + 1] = integral[i] + (length / m) / size(piece.at((i + 0.5) / m));
  const int n = std::max(piece.min_segments, static_cast<int>(std::ceil(integral[m] - 1e-9)));
  for (int k = 0, i = 0; k < n; ++k) {
    const double target = integral[m] * k / n;
    while (i < m && integral[i + 1] <= target) ++i;
    const double step = i < m ? integral[i + 1] - integral[i] : 1.0;
    t.push_back((i + (i < m ? (target - integral[i]) / step : 0.0)) / m);
  }
  return t;
}

}  // namespace

BoundarySegments cut_boundary(const PlanarDomain& domain, const SizeField& size) {
  BoundarySegments out;
  for (const auto& loop : domain.loops) {
    const int first = static_cast<int>(out.points.size());
    out.loop_begin.push_back(static_cast<int>(out.segments.size()));
    std::vector<int> point_piece;  // the piece a point starts a segment of
    for (const BoundaryPiece& piece : loop) {
      out.pieces.push_back(&piece);
      for (double t : parameters(piece, size)) {
        out.points.push_back(piece.at(t));
        point_piece.push_back(static_cast<int>(out.pieces.size()) - 1);
      }
    }
    const int n = static_cast<int>(point_piece.size());
    if (n < 3) throw MeshError("a boundary loop needs at least three segments");
    for (int k = 0; k < n; ++k) {
      out.segments.push_back({first + k, first + (k + 1) % n});
      out.piece.push_back(point_piece[k]);
    }
  }
  out.loop_begin.push_back(static_cast<int>(out.segments.size()));
  return out;
}

}  // namespace fsi
