// Inside the PETSc plugin: "petsc-iterative"'s saddle point K = [A_u Bᵀ; B D] by its
// blocks, split by the fields (velocity u, pressure p; this rank's rows of each). The
// iterative set-up takes them from K's rows (split_blocks) and then needs K no more: the caller
// frees K before the rest of the set-up, the memory's peak (docs/performance.md, "K
// freed before the set-up"). From the blocks come the Schur complement's preconditioning
// matrix S_p (schur_matrix), the preconditioner (petsc_schur.hpp) and the operator the
// Krylov method multiplies by (petsc_block_operator.hpp).
#pragma once

#include <petscmat.h>

#include "fluid/petsc_plugin.hpp"

#include <string>
#include <vector>

namespace fsi {

struct KBlocks {
  Mat A_u = nullptr, Bt = nullptr, D = nullptr;
  Mat B = nullptr;  // null where K is its own transpose: Bᵀ's transpose then
  bool taken() const { return A_u != nullptr; }
  void free();
};

// K's blocks (new matrices), straight from m, this rank's rows of K in PETSc's numbering:
// a block holds this rank's rows of its row field, numbered among that field's
// unknowns (is_pressure flags all n), as the index sets split them. own_transpose: K
// equals Kᵀ bit for bit (checked by the caller), so that B is not made. "" or the error.
std::string split_blocks(const PetscCsr& m, const std::vector<char>& is_pressure, bool own_transpose,
                         KBlocks& out);

// The same from m, this rank's rows of K by columns in the caller's numbering
// (petsc_plugin.hpp), in two passes over m (a count, a fill in PETSc's order of the
// columns): B made too. "" or the error.
std::string split_columns(const PetscColumns& m, const std::vector<char>& is_pressure, KBlocks& out);

// S_p = D − B diag(A_u)⁻¹ Bᵀ − M_w (M null: without it), a new matrix: the reasons are
// petsc_plugin.cpp's (finish_iterative). "" or the error.
std::string schur_matrix(const KBlocks& k, Mat M, Mat& S);

}  // namespace fsi
