// The P2 (quadratic Lagrange) space on a triangle mesh, for structure.element = "P2"
// (SPEC §11, issue 14): nodes at the vertices (indices 0 … nv−1, the mesh's) and at
// the edge midpoints (nv … nv + ne − 1), six per triangle, and the six basis functions
// in barycentric coordinates,
//     N_a = λ_a (2λ_a − 1) (a = 0, 1, 2),   N_{3+k} = 4 λ_k λ_{k+1} (the edge k → k+1),
// with ∇N_a = (4λ_a − 1) ∇λ_a and ∇N_{3+k} = 4 (λ_{k+1} ∇λ_k + λ_k ∇λ_{k+1}).
// The edges are straight: a curved boundary (a .geo arc) is met at its vertices only,
// an O(h³) geometric error, below P2's O(h³) in L².
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>
#include <utility>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

class P2Space {
 public:
  explicit P2Space(const Mesh& mesh);  // refers to `mesh`: it must outlive the space
  explicit P2Space(const Mesh&& mesh) = delete;

  const Mesh& mesh() const { return mesh_; }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  const std::vector<Point>& nodes() const { return nodes_; }
  // Triangle t's six nodes: its vertices, then the midpoints of edges 0→1, 1→2, 2→0.
  const std::array<int, 6>& element(int t) const { return elements_[t]; }
  // The node at the middle of the boundary edge e (one of mesh.boundary_edges).
  int midpoint_of(const BoundaryEdge& e) const;
  // Sorted nodes on the edges labelled `label`: their vertices and midpoints.
  std::vector<int> nodes_on(int label) const;

 private:
  const Mesh& mesh_;
  std::vector<Point> nodes_;
  std::vector<std::array<int, 6>> elements_;
  std::vector<std::vector<std::pair<int, int>>> edge_of_vertex_;  // v → (w > v, midpoint node)
};

// The six P2 basis values and gradients at barycentric point λ of triangle T.
struct P2Values {
  std::array<double, 6> N;
  Eigen::Matrix<double, 6, 2> grad;  // row i: ∇N_i
};
P2Values p2_values(const P1Triangle& T, const Eigen::Vector3d& lambda);

// The nodal mesh of a P2 space: its nodes as vertices (same indices), each triangle cut
// into four at its edge midpoints, each boundary edge into two with its label. A P2
// displacement (dof(node, c) = c·n + node) is then a P1 displacement of this mesh, and
// its piecewise-linear interpolant through the nodes is what the runs draw, write and
// give the fluid as the deformed structure (χ, the figures, the gap's candidates, the
// contact rows: docs/theory.md, "P2").
Mesh nodal_mesh(const P2Space& space);

// A P2 space that owns its mesh: what a run keeps beside the structure's solver.
struct OwnedP2Space {
  explicit OwnedP2Space(Mesh m) : mesh(std::move(m)), space(mesh) {}
  OwnedP2Space(const OwnedP2Space&) = delete;
  OwnedP2Space& operator=(const OwnedP2Space&) = delete;
  const Mesh mesh;  // the element mesh (straight-sided triangles)
  const P2Space space;
};

// kernel(t, element nodes, basis values, position, dx) at every point of `rule` on every
// triangle: the P2 assemblies' one loop (solid/p2_elasticity, coupling/p2_force).
template <class Kernel>
void integrate_p2(const P2Space& space, const TriangleRule& rule, Kernel&& kernel) {
  const Mesh& mesh = space.mesh();
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P1Triangle T(mesh, t);
    for (std::size_t q = 0; q < rule.w.size(); ++q)
      kernel(t, space.element(t), p2_values(T, rule.lambda[q]), T.point(rule.lambda[q]),
             rule.w[q] * T.area);
  }
}

// A P2 vector field w (2n, dof(node, c) = c·n + node) at a point of an element with
// nodes `nodes` and basis values `v` there: its value and gradient (row c = ∇w_c).
struct P2VectorAt {
  Point value = Point::Zero();
  Eigen::Matrix2d grad = Eigen::Matrix2d::Zero();
};
P2VectorAt p2_vector_at(const std::array<int, 6>& nodes, const P2Values& v, const Eigen::VectorXd& w, int n);

}  // namespace fsi
