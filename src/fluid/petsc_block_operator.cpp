#include "fluid/petsc_block_operator.hpp"

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

struct Operator {
  KBlocks k;        // the shell's own references
  FieldVectors v;   // a: x's fields, b: y's
};

PetscErrorCode destroy_operator(Mat op) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  if (!o) return 0;
  o->k.free();
  o->v.free();
  delete o;
  return 0;
}

// y = K x: y_u = A_u x_u + Bᵀ x_p, y_p = B x_u + D x_p.
PetscErrorCode multiply(Mat op, Vec x, Vec y) {
  Operator* o = nullptr;
  PetscCall(MatShellGetContext(op, &o));
  const KBlocks& k = o->k;
  FieldVectors& v = o->v;
  PetscCall(v.split(x));
  PetscCall(MatMult(k.A_u, v.a_u, v.b_u));
  PetscCall(MatMultAdd(k.Bt, v.a_p, v.b_u, v.b_u));
  PetscCall(MatMult(k.D, v.a_p, v.b_p));
  if (k.B)
    PetscCall(MatMultAdd(k.B, v.a_u, v.b_p, v.b_p));
  else
    PetscCall(MatMultTransposeAdd(k.Bt, v.a_u, v.b_p, v.b_p));
  return v.join(v.b_u, v.b_p, y);
}

std::string hold(Mat m, Mat& into) {
  if (m) FSI_TRY(PetscObjectReference(reinterpret_cast<PetscObject>(m)));
  into = m;
  return "";
}

}  // namespace

std::string make_block_operator(const KBlocks& k, IS u, IS p, Vec whole, Mat& op) {
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
  return o->v.make(k.Bt, whole, u, p);
}

}  // namespace fsi
