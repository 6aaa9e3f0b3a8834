#include "fluid/petsc_block_operator.hpp"

#include <cmath>

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

struct Operator {
  KBlocks k;                        // the shell's own references
  std::shared_ptr<FieldVectors> v;  // a: x's fields, b: y's (the preconditioner's too)
};

PetscErrorCode destroy_operator(Mat op) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  if (!o) return 0;
  o->k.free();
  delete o;
  return 0;
}

// (b_u, b_p) = K x by fields: b_u = A_u x_u + Bᵀ x_p, b_p = B x_u + D x_p.
PetscErrorCode multiply_fields(const Operator& o, Vec x) {
  const KBlocks& k = o.k;
  FieldVectors& v = *o.v;
  PetscCall(v.split(x));
  PetscCall(MatMult(k.A_u, v.a_u, v.b_u));
  PetscCall(MatMultAdd(k.Bt, v.a_p, v.b_u, v.b_u));
  PetscCall(MatMult(k.D, v.a_p, v.b_p));
  if (k.B)
    PetscCall(MatMultAdd(k.B, v.a_u, v.b_p, v.b_p));
  else
    PetscCall(MatMultTransposeAdd(k.Bt, v.a_u, v.b_p, v.b_p));
  return 0;
}

// y = K x.
PetscErrorCode multiply(Mat op, Vec x, Vec y) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  PetscCall(multiply_fields(*o, x));
  return o->v->join(o->v->b_u, o->v->b_p, y);
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

// ‖b − K x‖ in the fields' vectors: no whole vector more (12 bytes a triangle beside
// the set-up).
std::string block_residual_norm(Mat op, Vec x, Vec b, PetscReal& norm) {
  Operator* o = nullptr;
  FSI_TRY(MatShellGetContext(op, &o));
  FSI_TRY(multiply_fields(*o, x));
  FieldVectors& v = *o->v;
  FSI_TRY(v.split(b));
  FSI_TRY(VecAXPY(v.a_u, -1.0, v.b_u));
  FSI_TRY(VecAXPY(v.a_p, -1.0, v.b_p));
  PetscReal r_u = 0, r_p = 0;
  FSI_TRY(VecNorm(v.a_u, NORM_2, &r_u));
  FSI_TRY(VecNorm(v.a_p, NORM_2, &r_p));
  norm = std::hypot(r_u, r_p);
  return "";
}

}  // namespace fsi
