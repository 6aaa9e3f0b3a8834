// Points sorted along a Hilbert curve through their bounding box: consecutive points
// are near each other, and any run of consecutive points covers a compact part of the
// plane. Its use: numbering a mesh's vertices so that PETSc's contiguous blocks of
// rows, one per MPI rank, are compact parts of the domain (StokesAssembler::curve_rank).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace fsi {

// order[k] = the index of the k-th point along the curve (a permutation of the
// points). The box is divided into 2^16 × 2^16 cells; points in one cell keep their
// order (a stable sort). A flat or empty box is allowed: a zero extent maps to one
// column or row of cells.
std::vector<int> hilbert_order(const std::vector<Point>& points);

// The position along the curve of cell (x, y) of a 2^bits × 2^bits grid.
unsigned long long hilbert_index(unsigned x, unsigned y, int bits);

}  // namespace fsi
