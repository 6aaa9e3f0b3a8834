#include "mesh/lattice_mesher.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "mesh/constrained_delaunay.hpp"
#include "mesh/lattice_points.hpp"
#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// Delaunay refinement splits triangles with an edge longer than this times h(x):
// none of a lattice's (their edges are at most h), nor the layer along the
// boundary, which the angle improvement evens out; but the transition of a band
// refinement, which has no lattice, is filled to about h(x) (Delaunay refinement
// leaves edges of 0.6–0.9 times its bound).
constexpr double kMaxEdgeOverSize = 1.4;

std::pair<int, int> key(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

// The piece of each boundary edge. An edge the refinement made is part of a chain of
// them between two input points (the ends of the input segment it split); its new
// points are moved onto the circle where the piece is one (they were on the chord).
std::vector<int> edge_pieces(DelaunayMesh& dm, const BoundarySegments& b) {
  const int inputs = static_cast<int>(b.points.size());
  std::map<std::pair<int, int>, int> segment_of;
  for (int s = 0; s < static_cast<int>(b.segments.size()); ++s)
    segment_of[key(b.segments[s][0], b.segments[s][1])] = s;
  std::map<int, std::vector<int>> edges_at;  // a boundary vertex → its boundary edges
  for (int e = 0; e < static_cast<int>(dm.boundary_edges.size()); ++e)
    for (int v : dm.boundary_edges[e]) edges_at[v].push_back(e);
  std::vector<int> piece(dm.boundary_edges.size(), -1);
  for (int e = 0; e < static_cast<int>(dm.boundary_edges.size()); ++e) {
    if (piece[e] >= 0) continue;
    const auto [p, q] = dm.boundary_edges[e];
    if (p < inputs && q < inputs) {
      const auto it = segment_of.find(key(p, q));
      if (it == segment_of.end())
        throw MeshError("a boundary edge joins two points of different segments");
      piece[e] = b.piece[it->second];
      continue;
    }
    if (p >= inputs && q >= inputs) continue;  // reached from the chain's input end
    // Walk from the input end through the new points to the other input end.
    std::vector<int> chain = {e}, added;
    int from = p < inputs ? p : q, at = p < inputs ? q : p;
    const int start = from;
    while (at >= inputs) {
      added.push_back(at);
      const std::vector<int>& two = edges_at[at];
      if (two.size() != 2) throw MeshError("a refined boundary edge is not part of a chain");
      const int next = two[0] == chain.back() ? two[1] : two[0];
      chain.push_back(next);
      const auto [r, s] = dm.boundary_edges[next];
      from = at;
      at = r == from ? s : r;
    }
    const auto it = segment_of.find(key(start, at));
    if (it == segment_of.end()) throw MeshError("a refined boundary edge lies on no input segment");
    const int k = b.piece[it->second];
    for (int c : chain) piece[c] = k;
    if (const BoundaryPiece& circle = *b.pieces[k]; circle.circle())
      for (int v : added)
        dm.vertices[v] = circle.c + circle.r * (dm.vertices[v] - circle.c).normalized();
  }
  return piece;
}

// A boundary vertex between two edges of one segment slides along it; the ends of the
// pieces (corners, the ends of Γ_C), the points of circles (Freedom) and of pieces that
// may not slide stay.
std::vector<Freedom> freedom(const DelaunayMesh& dm, const std::vector<int>& piece,
                             const BoundarySegments& b) {
  std::vector<Freedom> f(dm.vertices.size());
  std::vector<int> piece_at(dm.vertices.size(), -1);
  for (std::size_t e = 0; e < dm.boundary_edges.size(); ++e)
    for (int v : dm.boundary_edges[e]) {
      if (piece_at[v] >= 0 && piece_at[v] != piece[e]) {
        f[v].kind = Freedom::fixed;
        continue;
      }
      piece_at[v] = piece[e];
      const BoundaryPiece& p = *b.pieces[piece[e]];
      f[v] = p.circle() || !p.slide ? Freedom{Freedom::fixed} : Freedom{Freedom::line, p.a, p.b};
    }
  return f;
}

Mesh to_mesh(DelaunayMesh&& dm, const std::vector<int>& piece, const BoundarySegments& b,
             const PlanarDomain& domain) {
  Mesh mesh;
  mesh.vertices = std::move(dm.vertices);
  mesh.triangles = std::move(dm.triangles);
  mesh.label_names = domain.labels;
  for (std::size_t e = 0; e < dm.boundary_edges.size(); ++e)
    mesh.boundary_edges.push_back({dm.boundary_edges[e], b.pieces[piece[e]]->label});
  return mesh;
}

}  // namespace

Mesh lattice_mesh(const PlanarDomain& domain, const SizeField& size, LatticeReport* report) {
  const BoundarySegments boundary = cut_boundary(domain, size);
  DelaunayInput input{boundary.points, boundary.segments, lattice_points(boundary, size)};
  DelaunayMesh dm = constrained_delaunay(input, size, kMaxEdgeOverSize);
  const std::vector<int> piece = edge_pieces(dm, boundary);
  const AngleReport angles =
      improve_angles(dm.vertices, dm.triangles, freedom(dm, piece, boundary),
                     {.size = &size, .max_edge_over_size = kMaxEdgeOverSize});
  if (report) {
    report->lattice_points = static_cast<int>(input.interior.size());
    report->refinement_points =
        static_cast<int>(dm.vertices.size() - input.boundary.size() - input.interior.size());
    report->angles = angles;
  }
  return to_mesh(std::move(dm), piece, boundary, domain);
}

}  // namespace fsi
