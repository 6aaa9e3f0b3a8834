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

#include <memory>
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

// Two vectors a field (a_u, b_u of u's layout, a_p, b_p of p's) and the scatters between
// the whole vector and each field's: the work space of the operator by blocks and of
// the preconditioner. One set serves both (make_field_vectors): the Krylov method
// applies one, then the other, never one inside the other, and a set is 4 vectors of
// the velocity's and pressure's sizes, 48 bytes a fluid triangle, with its scatters'
// indices (docs/performance.md, "The run's later passes").
struct FieldVectors {
  Vec a_u = nullptr, a_p = nullptr, b_u = nullptr, b_p = nullptr;
  VecScatter to_u = nullptr, to_p = nullptr;
  FieldVectors() = default;
  FieldVectors(const FieldVectors&) = delete;
  FieldVectors& operator=(const FieldVectors&) = delete;
  ~FieldVectors();
  // whole → (a_u, a_p), and (u, p) → whole.
  PetscErrorCode split(Vec whole);
  PetscErrorCode join(Vec u, Vec p, Vec whole);
};

// A set for the layouts of Bᵀ (its rows u, its columns p) and of the whole vector,
// split into the index sets u and p. "" or the error (out then null).
std::string make_field_vectors(Mat Bt, Vec whole, IS u, IS p, std::shared_ptr<FieldVectors>& out);

}  // namespace fsi
