#include "mesh/angle_improvement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fsi {

double sine_squared_min_angle(const Point& a, const Point& b, const Point& c) {
  const double twice_area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  if (!(twice_area > 0)) return -1;
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const double longest = std::max({ab, bc, ca}), shortest = std::min({ab, bc, ca});
  // sin A = 2|T| / (b c) for the angle A opposite the shortest side a.
  return twice_area * twice_area / (longest * (ab + bc + ca - longest - shortest));
}

namespace {

class Improver {
 public:
  Improver(std::vector<Point>& v, std::vector<std::array<int, 3>>& t,
           const std::vector<Freedom>& freedom, double target, const AngleImprovement& options)
      : v_(v), t_(t), freedom_(freedom), target_(target), options_(options) {
    build_stars();
    build_neighbours();
  }

  int flip_pass();
  int move_pass();

 private:
  double quality(const std::array<int, 3>& t) const {
    return sine_squared_min_angle(v_[t[0]], v_[t[1]], v_[t[2]]);
  }
  bool bad(int t) const { return quality(t_[t]) < target_; }
  bool try_flip(int t, int k);
  // The smallest quality around `vertex` placed at `at`; stops early (returning it)
  // once one is not above `floor`; −1 if an edge at the vertex would be longer than
  // `reach` (a move never lengthens the longest edge: the size stays h(x)).
  double star_quality(int vertex, const Point& at, double floor = -INFINITY,
                      double reach = INFINITY) const;
  bool move(int vertex);
  void build_stars();
  void build_neighbours();

  std::vector<Point>& v_;
  std::vector<std::array<int, 3>>& t_;
  const std::vector<Freedom>& freedom_;
  double target_;
  const AngleImprovement& options_;
  std::vector<int> star_begin_, star_;  // vertex → its triangles (CSR)
  // The triangle across the edge opposite corner k; −1 on the boundary.
  std::vector<std::array<int, 3>> neighbour_;
};

void Improver::build_stars() {
  star_begin_.assign(v_.size() + 1, 0);
  for (const auto& t : t_)
    for (int k : t) ++star_begin_[k + 1];
  for (std::size_t i = 0; i < v_.size(); ++i) star_begin_[i + 1] += star_begin_[i];
  star_.assign(star_begin_.back(), 0);
  std::vector<int> fill(star_begin_.begin(), star_begin_.end() - 1);
  for (int t = 0; t < static_cast<int>(t_.size()); ++t)
    for (int k : t_[t]) star_[fill[k]++] = t;
}

void Improver::build_neighbours() {
  neighbour_.assign(t_.size(), {-1, -1, -1});
  for (int t = 0; t < static_cast<int>(t_.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int b = t_[t][(k + 1) % 3], c = t_[t][(k + 2) % 3];
      for (int s = star_begin_[b]; s < star_begin_[b + 1]; ++s) {
        const int u = star_[s];
        if (u != t && std::find(t_[u].begin(), t_[u].end(), c) != t_[u].end()) neighbour_[t][k] = u;
      }
    }
}

// The edge opposite corner k of t: a, b, c of t and d of its neighbour u become the
// triangles (a, b, d) and (a, d, c) if that raises the smaller quality of the two.
bool Improver::try_flip(int t, int k) {
  const int u = neighbour_[t][k];
  if (u < 0) return false;
  const int a = t_[t][k], b = t_[t][(k + 1) % 3], c = t_[t][(k + 2) % 3];
  int m = 0;
  while (t_[u][m] == b || t_[u][m] == c) ++m;
  const int d = t_[u][m];
  const std::array<int, 3> abd = {a, b, d}, adc = {a, d, c};
  const double before = std::min(quality(t_[t]), quality(t_[u]));
  if (!(std::min(quality(abd), quality(adc)) > before * (1 + 1e-12) + 1e-300)) return false;
  const auto across = [&](int tri, int vertex) {  // the neighbour opposite `vertex`
    const auto& x = t_[tri];
    return neighbour_[tri][vertex == x[0] ? 0 : vertex == x[1] ? 1 : 2];
  };
  const int t_ab = across(t, c), t_ca = across(t, b), u_bd = across(u, c), u_dc = across(u, b);
  const auto repoint = [&](int tri, int from, int to) {
    if (tri >= 0)
      for (int& n : neighbour_[tri])
        if (n == from) n = to;
  };
  repoint(u_bd, u, t);
  repoint(t_ca, t, u);
  t_[t] = abd;
  neighbour_[t] = {u_bd, u, t_ab};
  t_[u] = adc;
  neighbour_[u] = {u_dc, t_ca, t};
  return true;
}

int Improver::flip_pass() {
  std::vector<int> work;
  for (int t = 0; t < static_cast<int>(t_.size()); ++t)
    if (bad(t)) work.push_back(t);
  int flips = 0;
  // Each flip raises the sorted qualities: the passes end long before this.
  const std::size_t limit = 10 * t_.size() + 100;
  while (!work.empty() && static_cast<std::size_t>(flips) < limit) {
    const int t = work.back();
    work.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int u = neighbour_[t][k];
      if (try_flip(t, k)) {
        ++flips;
        work.push_back(t);
        work.push_back(u);
        break;
      }
    }
  }
  if (flips) build_stars();
  return flips;
}

double Improver::star_quality(int vertex, const Point& at, double floor, double reach) const {
  double q = INFINITY;
  for (int s = star_begin_[vertex]; s < star_begin_[vertex + 1] && q > floor; ++s) {
    std::array<Point, 3> p;
    for (int k = 0; k < 3; ++k) {
      const int w = t_[star_[s]][k];
      p[k] = w == vertex ? at : v_[w];
      if (w != vertex && (p[k] - at).norm() > reach) return -1;
    }
    q = std::min(q, sine_squared_min_angle(p[0], p[1], p[2]));
  }
  return q;
}

// Where a move to p lands: p itself, or its projection on the vertex's segment.
Point constrain(const Freedom& f, const Point& p) {
  if (f.kind != Freedom::line) return p;
  const Point d = f.b - f.a;
  return f.a + std::clamp((p - f.a).dot(d) / d.squaredNorm(), 0.0, 1.0) * d;
}

// A pattern search from the vertex's place (first trying its neighbours' centroid):
// eight directions (two along a segment), the best taken, the step halved when none
// improves.
bool Improver::move(int vertex) {
  const Freedom& f = freedom_[vertex];
  Point x = v_[vertex], centroid = Point::Zero();
  double reach = 0;
  int count = 0;
  for (int s = star_begin_[vertex]; s < star_begin_[vertex + 1]; ++s)
    for (int k : t_[star_[s]])
      if (k != vertex) centroid += v_[k], ++count, reach = std::max(reach, (v_[k] - x).norm());
  double best = star_quality(vertex, x);
  const double start = best;
  const double longest = reach;  // the search's step scale
  if (options_.size) reach = std::max(reach, options_.max_edge_over_size * (*options_.size)(x));
  if (count > 0) {
    const Point c = constrain(f, centroid / count);
    const double q = star_quality(vertex, c, best, reach);
    if (q > best) best = q, x = c;
  }
  static const double kDiagonal = std::numbers::sqrt2 / 2;
  static const double plane[8][2] = {
      {1, 0},  {kDiagonal, kDiagonal},   {0, 1},  {-kDiagonal, kDiagonal},
      {-1, 0}, {-kDiagonal, -kDiagonal}, {0, -1}, {kDiagonal, -kDiagonal}};
  for (double step = 0.05 * longest; step > 1e-3 * longest;) {
    std::array<Point, 8> tries;
    int n = 0;
    if (f.kind == Freedom::free) {
      for (const auto& d : plane) tries[n++] = x + step * Point(d[0], d[1]);
    } else {  // along the segment
      const Point along = (f.b - f.a).normalized();
      for (double sign : {1.0, -1.0}) tries[n++] = constrain(f, x + sign * step * along);
    }
    Point next = x;
    for (int i = 0; i < n; ++i) {
      const double q = star_quality(vertex, tries[i], best, reach);
      if (q > best) best = q, next = tries[i];
    }
    if (next == x) step /= 2;
    x = next;
  }
  if (!(best > start)) return false;
  v_[vertex] = x;
  return true;
}

int Improver::move_pass() {
  std::vector<char> visit(v_.size(), 0);
  for (int t = 0; t < static_cast<int>(t_.size()); ++t)
    if (bad(t))
      for (int k : t_[t]) visit[k] = freedom_[k].kind != Freedom::fixed;
  int moves = 0;
  for (int vertex = 0; vertex < static_cast<int>(v_.size()); ++vertex)
    if (visit[vertex] && move(vertex)) ++moves;
  return moves;
}

// The part of the mesh worth visiting: the triangles within two rings of the
// vertices of those under the target (a lattice's interior is never among them).
// Its vertices touching triangles outside stay fixed, and the edges on its rim are
// never flipped (no neighbour in the part), so nothing outside it changes.
struct Part {
  std::vector<int> triangles, vertices;  // global indices
  std::vector<Point> positions;
  std::vector<std::array<int, 3>> local_triangles;
  std::vector<Freedom> freedom;
};

Part part_to_improve(const std::vector<Point>& v, const std::vector<std::array<int, 3>>& t,
                     const std::vector<Freedom>& freedom, double target) {
  std::vector<int> star_begin(v.size() + 1, 0), star;
  for (const auto& tri : t)
    for (int k : tri) ++star_begin[k + 1];
  for (std::size_t i = 0; i < v.size(); ++i) star_begin[i + 1] += star_begin[i];
  star.resize(star_begin.back());
  std::vector<int> fill(star_begin.begin(), star_begin.end() - 1);
  for (int i = 0; i < static_cast<int>(t.size()); ++i)
    for (int k : t[i]) star[fill[k]++] = i;
  std::vector<char> in(t.size(), 0);
  std::vector<int> ring;
  for (int i = 0; i < static_cast<int>(t.size()); ++i)
    if (sine_squared_min_angle(v[t[i][0]], v[t[i][1]], v[t[i][2]]) < target) ring.push_back(i);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> next;
    for (int i : ring)
      for (int k : t[i])
        for (int s = star_begin[k]; s < star_begin[k + 1]; ++s)
          if (!in[star[s]]) in[star[s]] = 1, next.push_back(star[s]);
    ring = std::move(next);
  }
  Part part;
  std::vector<int> local(v.size(), -1);
  for (int i = 0; i < static_cast<int>(t.size()); ++i) {
    if (!in[i]) continue;
    part.triangles.push_back(i);
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      int& l = local[t[i][k]];
      if (l < 0) {
        l = static_cast<int>(part.vertices.size());
        part.vertices.push_back(t[i][k]);
        part.positions.push_back(v[t[i][k]]);
        bool rim = false;
        for (int s = star_begin[t[i][k]]; s < star_begin[t[i][k] + 1]; ++s)
          rim = rim || !in[star[s]];
        part.freedom.push_back(rim ? Freedom{Freedom::fixed} : freedom[t[i][k]]);
      }
      tri[k] = l;
    }
    part.local_triangles.push_back(tri);
  }
  return part;
}

}  // namespace

AngleReport improve_angles(std::vector<Point>& vertices, std::vector<std::array<int, 3>>& triangles,
                           const std::vector<Freedom>& freedom, const AngleImprovement& options) {
  const double s = std::sin(options.target_deg * std::numbers::pi / 180);
  Part part = part_to_improve(vertices, triangles, freedom, s * s);
  AngleReport report;
  if (part.triangles.empty()) return report;
  Improver improver(part.positions, part.local_triangles, part.freedom, s * s, options);
  for (int round = 0; round < options.rounds; ++round) {
    const int flips = improver.flip_pass(), moves = improver.move_pass();
    report.flips += flips;
    report.moves += moves;
    if (flips == 0 && moves == 0) break;
  }
  report.flips += improver.flip_pass();
  for (std::size_t i = 0; i < part.vertices.size(); ++i)
    vertices[part.vertices[i]] = part.positions[i];
  for (std::size_t i = 0; i < part.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      triangles[part.triangles[i]][k] = part.vertices[part.local_triangles[i][k]];
  return report;
}

}  // namespace fsi
