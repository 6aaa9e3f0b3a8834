#include "fluid/petsc_block_operator.hpp"

#include <cmath>

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

struct Operator {
  KBlocks k;                        // the shell's own references
  std::shared_ptr<FieldVectors> v;  // in: x's fields, out: y's (the preconditioner's too)
};

PetscErrorCode destroy_operator(Mat op) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  if (!o) return 0;
  o->k.free();
  delete o;
  return 0;
}

// (y_u, y_p) = K x by fields, x's fields (x_u, x_p) read: y_u = A_u x_u + Bᵀ x_p,
// y_p = B x_u + D x_p.
PetscErrorCode multiply_fields(const KBlocks& k, const FieldVectors& v, Vec y_u, Vec y_p) {
  PetscCall(MatMult(k.A_u, v.in_u, y_u));
  PetscCall(MatMultAdd(k.Bt, v.in_p, y_u, y_u));
  PetscCall(MatMult(k.D, v.in_p, y_p));
  if (k.B)
    PetscCall(MatMultAdd(k.B, v.in_u, y_p, y_p));
  else
    PetscCall(MatMultTransposeAdd(k.Bt, v.in_u, y_p, y_p));
  return 0;
}

// y = K x.
PetscErrorCode multiply(Mat op, Vec x, Vec y) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  FieldVectors& v = *o->v;
  PetscCall(v.read(x));
  PetscCall(v.write(y));
  PetscCall(multiply_fields(o->k, v, v.out_u, v.out_p));
  PetscCall(v.end_read(x));
  return v.end_write(y);
}

std::string hold(Mat m, Mat& into) {
  if (m) FSI_TRY(PetscObjectReference(reinterpret_cast<PetscObject>(m)));
  into = m;
  return "";
}

}  // namespace

std::string make_block_operator(const KBlocks& k, std::shared_ptr<FieldVectors> v, Vec whole, Mat& op) {
  PetscInt local = 0, global = 0;
  FSI_TRY(VecGetLocalSize(whole, &local));
  FSI_TRY(VecGetSize(whole, &global));
  auto* o = new Operator;
  if (const PetscErrorCode code = MatCreateShell(PetscObjectComm(reinterpret_cast<PetscObject>(whole)), local,
                                                 local, global, global, o, &op)) {
    delete o;
    return petsc_error_text(code, "MatCreateShell");
  }
  FSI_TRY(MatShellSetOperation(op, MATOP_DESTROY, reinterpret_cast<void (*)(void)>(destroy_operator)));
  FSI_TRY(MatShellSetOperation(op, MATOP_MULT, reinterpret_cast<void (*)(void)>(multiply)));
  for (auto [m, into] : {std::pair{k.A_u, &o->k.A_u}, {k.Bt, &o->k.Bt}, {k.B, &o->k.B}, {k.D, &o->k.D}})
    if (std::string e = hold(m, *into); !e.empty()) return e;
  o->v = std::move(v);
  return "";
}

// ‖b − K x‖ in the fields' work vectors: no whole vector more (12 bytes a triangle
// beside the set-up).
std::string block_residual_norm(Mat op, Vec x, Vec b, PetscReal& norm) {
  Operator* o = nullptr;
  FSI_TRY(MatShellGetContext(op, &o));
  FieldVectors& v = *o->v;
  FSI_TRY(v.read(x));
  FSI_TRY(multiply_fields(o->k, v, v.w_u, v.w_p));
  FSI_TRY(v.end_read(x));
  FSI_TRY(v.read(b));
  FSI_TRY(VecAXPY(v.w_u, -1.0, v.in_u));  // K x − b: the same norm
  FSI_TRY(VecAXPY(v.w_p, -1.0, v.in_p));
  FSI_TRY(v.end_read(b));
  PetscReal r_u = 0, r_p = 0;
  FSI_TRY(VecNorm(v.w_u, NORM_2, &r_u));
  FSI_TRY(VecNorm(v.w_p, NORM_2, &r_p));
  norm = std::hypot(r_u, r_p);
  return "";
}

}  // namespace fsi
