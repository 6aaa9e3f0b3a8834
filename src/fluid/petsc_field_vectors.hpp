// Inside the PETSc plugin: a whole vector of the saddle point seen by its fields,
// velocity u and pressure p (this rank's rows of each), for the operator by blocks
// (petsc_block_operator.hpp) and the Schur preconditioner (petsc_schur.hpp).
#pragma once

#include <petscvec.h>

#include <memory>
#include <string>

namespace fsi {

// in_u, in_p: the fields of a vector read (read ... end_read); out_u, out_p: those of a
// vector written (write ... end_write); w_u, w_p: work vectors of each field's layout.
// Where every rank's rows are its velocity's, then its pressure's (PetscSolver's order:
// the assembler's field by field within each rank's block), the fields are views of
// the whole vector's own array: no copy. Otherwise they are copies, by scatters: whole
// → (in_u, in_p) at read, (out_u, out_p) → whole at end_write. At 930 681 triangles
// the copies, 8 a Krylov iteration, took 0.31 s on one rank and a rank on two
// (docs/performance.md, "The bubbles shared, and the fields as views").
// One set serves the operator and the preconditioner: the Krylov method applies one,
// then the other, never one inside the other.
struct FieldVectors {
  Vec in_u = nullptr, in_p = nullptr, out_u = nullptr, out_p = nullptr;
  Vec w_u = nullptr, w_p = nullptr;
  VecScatter to_u = nullptr, to_p = nullptr;  // null for views
  FieldVectors() = default;
  FieldVectors(const FieldVectors&) = delete;
  FieldVectors& operator=(const FieldVectors&) = delete;
  ~FieldVectors();
  bool views() const { return to_u == nullptr; }
  PetscErrorCode read(Vec whole);
  PetscErrorCode end_read(Vec whole);
  PetscErrorCode write(Vec whole);
  PetscErrorCode end_write(Vec whole);

 private:
  const PetscScalar* read_array_ = nullptr;
  PetscScalar* write_array_ = nullptr;
};

// A set for the whole vector's layout split into the index sets u and p (this rank's
// rows of each). "" or the error (out then null).
std::string make_field_vectors(Vec whole, IS u, IS p, std::shared_ptr<FieldVectors>& out);

}  // namespace fsi
