#include "fem/uniform_refinement.hpp"

#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace fsi {
namespace {

// The fine vertex at barycentric lattice point (i, j, k), i + j + k = m, of triangle
// t: a coarse vertex at a corner, shared along an edge (keyed by its end vertices,
// the smaller first, and the distance from it), the triangle's own inside.
class LatticeVertices {
 public:
  LatticeVertices(const Mesh& mesh, int m, UniformRefinement& out) : mesh_(mesh), m_(m), out_(out) {}

  int at(int t, int i, int j, int k) {
    const auto& tri = mesh_.triangles[t];
    const int w[3] = {i, j, k};
    int nonzero = 0, corner = -1;
    for (int a = 0; a < 3; ++a)
      if (w[a] > 0) ++nonzero, corner = a;
    if (nonzero == 1) return tri[corner];  // coarse vertex: same index
    std::tuple<int, int, int, int> key;
    if (nonzero == 2) {
      int a = -1, b = -1;
      for (int c = 0; c < 3; ++c)
        if (w[c] > 0) (a < 0 ? a : b) = c;
      int va = tri[a], vb = tri[b], wa = w[a];
      if (va > vb) std::swap(va, vb), wa = w[b];
      key = {va, vb, wa, -1};
    } else {
      key = {-1, t, i, j};
    }
    const auto [it, added] = index_.try_emplace(key, static_cast<int>(out_.fine.vertices.size()));
    if (added) {
      Point x = Point::Zero();
      for (int a = 0; a < 3; ++a) {
        x += (static_cast<double>(w[a]) / m_) * mesh_.vertices[tri[a]];
        if (w[a] > 0) weights_.emplace_back(it->second, tri[a], static_cast<double>(w[a]) / m_);
      }
      out_.fine.vertices.push_back(x);
    }
    return it->second;
  }

  std::vector<Eigen::Triplet<double>> weights_;

 private:
  const Mesh& mesh_;
  int m_;
  UniformRefinement& out_;
  std::map<std::tuple<int, int, int, int>, int> index_;
};

}  // namespace

UniformRefinement refine_uniformly(const Mesh& mesh, int m) {
  if (m < 1) throw std::invalid_argument("refine_uniformly: m = " + std::to_string(m) + " (allowed: m >= 1)");
  UniformRefinement r;
  r.fine.vertices = mesh.vertices;  // the coarse vertices keep their indices
  LatticeVertices lattice(mesh, m, r);
  for (int v = 0; v < mesh.num_vertices(); ++v) lattice.weights_.emplace_back(v, v, 1.0);
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j) {
        const int k = m - i - j;  // the sub-triangle with lattice corner (i, j, k) pointing like its parent
        r.fine.triangles.push_back({lattice.at(t, i + 1, j, k - 1), lattice.at(t, i, j + 1, k - 1), lattice.at(t, i, j, k)});
        if (i + j + 1 < m)  // the inverted one beside it
          r.fine.triangles.push_back(
              {lattice.at(t, i, j + 1, k - 1), lattice.at(t, i + 1, j, k - 1), lattice.at(t, i + 1, j + 1, k - 2)});
      }
  r.P.resize(r.fine.num_vertices(), mesh.num_vertices());
  r.P.setFromTriplets(lattice.weights_.begin(), lattice.weights_.end());
  return r;
}

}  // namespace fsi
