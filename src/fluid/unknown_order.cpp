// StokesAssembler's orders of the unknowns (stokes_assembler.hpp): a fill-reducing
// one for the direct solvers (dof_rank) and one that keeps each MPI rank's block of
// rows a compact part of the domain (curve_rank).
#include <Eigen/SparseCore>
#include <future>
#include <vector>

#include "fluid/sparse_solver.hpp"
#include "fluid/stokes_assembler.hpp"
#include "mesh/hilbert_order.hpp"

namespace fsi {
namespace {

// METIS nested dissection of the vertex graph: perm[k] = the k-th vertex.
std::vector<int> vertex_nested_dissection(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  const std::vector<std::vector<int>> adjacent = vertex_neighbours(mesh);
  Eigen::SparseMatrix<double> graph(nv, nv);
  std::size_t nnz = 0;
  for (const auto& list : adjacent) nnz += list.size();
  graph.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  graph.outerIndexPtr()[0] = 0;
  for (int v = 0, k = 0; v < nv; ++v) {
    for (int w : adjacent[v]) graph.innerIndexPtr()[k] = w, graph.valuePtr()[k++] = 1.0;
    graph.outerIndexPtr()[v + 1] = graph.outerIndexPtr()[v] + static_cast<int>(adjacent[v].size());
  }
  return metis_ordering(graph);
}

}  // namespace

// The order is needed only by the first far-field factorisation, after the solver's
// set-up, the point locator, the first χ and the far field's assembly: computed
// meanwhile on the second core (METIS on the vertex graph takes 20–25 ms at
// hF = 0.01, 5–7 % of Table 1's row 13). Where no thread can be started, it is
// computed when first asked for.
void StokesAssembler::order_in_background() {
  if (!dof_rank_.empty() || vertex_order_.valid()) return;
  const Mesh& mesh = mesh_;
  vertex_order_ = std::async(std::launch::async | std::launch::deferred,
                             [&mesh] { return vertex_nested_dissection(mesh); });
}

// A fill-reducing order of the unknowns, computed once per mesh: METIS nested
// dissection of the vertex graph, each vertex's v1, v2, p kept together. On the
// vertex graph (a third of the nodes, a ninth of the edges of the dof graph) METIS
// is several times faster than on K, for a fill within a few per cent; it serves
// every far-field factorisation of the run.
const std::vector<int>& StokesAssembler::dof_rank() {
  if (!dof_rank_.empty()) return dof_rank_;
  // A failed order (get() rethrows METIS's failure) leaves the future invalid: a
  // second request computes it here.
  dof_rank_ = rank_of_unknowns(vertex_order_.valid() ? vertex_order_.get() : vertex_nested_dissection(mesh_));
  return dof_rank_;
}

// On several MPI ranks, each rank's block of the dof_rank() order would be a part of a
// nested dissection, its separators gathered last (the last rank's block), and METIS
// on the vertex graph takes seconds at a million unknowns. A Hilbert curve gives
// compact blocks in O(n log n): at 1.4 million unknowns on two ranks the PETSc
// analysis took 0.17 s instead of 2.8 s, for as many GMRES iterations (93; 111
// instead of 120 at 2.85 million; measured in the previous try of this change,
// bench/petsc_study.py, docs/performance.md).
std::vector<int> StokesAssembler::curve_rank() const { return rank_of_unknowns(hilbert_order(mesh_.vertices)); }

std::vector<int> StokesAssembler::rank_of_unknowns(const std::vector<int>& vertices) const {
  const int nv = mesh_.num_vertices();
  std::vector<int> rank(free_.size(), 0);
  for (int position = 0; position < nv; ++position)
    for (int c = 0; c < 3; ++c) {
      const int r = free_index_[c * nv + vertices[static_cast<std::size_t>(position)]];
      if (r >= 0) rank[static_cast<std::size_t>(r)] = 3 * position + c;
    }
  return rank;
}

}  // namespace fsi
