#include "fluid/petsc_field_vectors.hpp"

#include <petscis.h>

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

// Whether this rank's rows of u are [first, first + n_u) and of p the rest, on every rank.
std::string fields_in_order(Vec whole, IS u, IS p, bool& in_order) {
  PetscInt first = 0, last = 0, n_u = 0, n_p = 0;
  FSI_TRY(VecGetOwnershipRange(whole, &first, &last));
  FSI_TRY(ISGetLocalSize(u, &n_u));
  FSI_TRY(ISGetLocalSize(p, &n_p));
  // Where contiguous, start is the first index's offset from first.
  PetscInt u_start = -1, p_start = -1;
  PetscBool u_block = PETSC_FALSE, p_block = PETSC_FALSE;
  FSI_TRY(ISContiguousLocal(u, first, last, &u_start, &u_block));
  FSI_TRY(ISContiguousLocal(p, first, last, &p_start, &p_block));
  const bool here = n_u + n_p == last - first && (n_u == 0 || (u_block && u_start == 0)) &&
                    (n_p == 0 || (p_block && p_start == n_u));
  int all = here ? 1 : 0;
  FSI_TRY(MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, PetscObjectComm(reinterpret_cast<PetscObject>(whole)))
              ? PETSC_ERR_MPI
              : 0);
  in_order = all == 1;
  return "";
}

// A vector of the field's layout (its rows here, n_global in all) without an array of
// its own: an array is placed in it.
std::string view(Vec whole, PetscInt n_local, PetscInt n_global, Vec& out) {
  FSI_TRY(VecCreateMPIWithArray(PetscObjectComm(reinterpret_cast<PetscObject>(whole)), 1, n_local, n_global,
                                nullptr, &out));
  return "";
}

}  // namespace

std::string make_field_vectors(Vec whole, IS u, IS p, std::shared_ptr<FieldVectors>& out) {
  bool in_order = false;
  if (std::string e = fields_in_order(whole, u, p, in_order); !e.empty()) return e;
  auto v = std::make_shared<FieldVectors>();
  PetscInt n_u = 0, n_p = 0, N_u = 0, N_p = 0;
  FSI_TRY(ISGetLocalSize(u, &n_u));
  FSI_TRY(ISGetLocalSize(p, &n_p));
  FSI_TRY(ISGetSize(u, &N_u));
  FSI_TRY(ISGetSize(p, &N_p));
  const MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(whole));
  FSI_TRY(VecCreateMPI(comm, n_u, N_u, &v->w_u));
  FSI_TRY(VecCreateMPI(comm, n_p, N_p, &v->w_p));
  if (in_order) {
    for (Vec* f : {&v->in_u, &v->out_u})
      if (std::string e = view(whole, n_u, N_u, *f); !e.empty()) return e;
    for (Vec* f : {&v->in_p, &v->out_p})
      if (std::string e = view(whole, n_p, N_p, *f); !e.empty()) return e;
  } else {
    for (Vec* f : {&v->in_u, &v->out_u}) FSI_TRY(VecDuplicate(v->w_u, f));
    for (Vec* f : {&v->in_p, &v->out_p}) FSI_TRY(VecDuplicate(v->w_p, f));
    FSI_TRY(VecScatterCreate(whole, u, v->in_u, nullptr, &v->to_u));
    FSI_TRY(VecScatterCreate(whole, p, v->in_p, nullptr, &v->to_p));
  }
  out = std::move(v);
  return "";
}

PetscErrorCode FieldVectors::read(Vec whole) {
  if (views()) {
    PetscInt n_u = 0;
    PetscCall(VecGetLocalSize(in_u, &n_u));
    PetscCall(VecGetArrayRead(whole, &read_array_));
    PetscCall(VecPlaceArray(in_u, read_array_));
    return VecPlaceArray(in_p, read_array_ + n_u);
  }
  PetscCall(VecScatterBegin(to_u, whole, in_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_u, whole, in_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterBegin(to_p, whole, in_p, INSERT_VALUES, SCATTER_FORWARD));
  return VecScatterEnd(to_p, whole, in_p, INSERT_VALUES, SCATTER_FORWARD);
}

PetscErrorCode FieldVectors::end_read(Vec whole) {
  if (!views()) return 0;
  PetscCall(VecResetArray(in_u));
  PetscCall(VecResetArray(in_p));
  return VecRestoreArrayRead(whole, &read_array_);
}

PetscErrorCode FieldVectors::write(Vec whole) {
  if (!views()) return 0;
  PetscInt n_u = 0;
  PetscCall(VecGetLocalSize(out_u, &n_u));
  PetscCall(VecGetArray(whole, &write_array_));
  PetscCall(VecPlaceArray(out_u, write_array_));
  return VecPlaceArray(out_p, write_array_ + n_u);
}

PetscErrorCode FieldVectors::end_write(Vec whole) {
  if (views()) {
    PetscCall(VecResetArray(out_u));
    PetscCall(VecResetArray(out_p));
    return VecRestoreArray(whole, &write_array_);
  }
  PetscCall(VecScatterBegin(to_u, out_u, whole, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(to_u, out_u, whole, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterBegin(to_p, out_p, whole, INSERT_VALUES, SCATTER_REVERSE));
  return VecScatterEnd(to_p, out_p, whole, INSERT_VALUES, SCATTER_REVERSE);
}

FieldVectors::~FieldVectors() {
  VecDestroy(&in_u), VecDestroy(&in_p), VecDestroy(&out_u), VecDestroy(&out_p);
  VecDestroy(&w_u), VecDestroy(&w_p);
  VecScatterDestroy(&to_u), VecScatterDestroy(&to_p);
}

}  // namespace fsi
