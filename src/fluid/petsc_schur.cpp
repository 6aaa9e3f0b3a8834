#include "fluid/petsc_schur.hpp"

#include "fluid/petsc_blocks.hpp"
#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

// What P⁻¹ holds between its applications.
struct Factorisation {
  KSP ksp_u = nullptr, ksp_p = nullptr;  // one V-cycle on A_u, one on S
  Mat Bt = nullptr;                      // K's (u, p) block
  std::shared_ptr<FieldVectors> v;       // in: r's fields, out: y's (the operator's too)
};

PetscErrorCode destroy_factorisation(PC pc) {
  Factorisation* f = nullptr;
  PetscCall(PCShellGetContext(pc, &f));
  if (!f) return 0;
  KSPDestroy(&f->ksp_u), KSPDestroy(&f->ksp_p), MatDestroy(&f->Bt);
  delete f;
  return 0;
}

// An inner solve that failed (a hierarchy's breakdown) fails the outer preconditioner:
// the Krylov method then stops with DIVERGED_PC_FAILED.
PetscErrorCode inner_solve(PC pc, KSP ksp, Vec b, Vec x) {
  PetscCall(KSPSolve(ksp, b, x));
  KSPConvergedReason reason;
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  if (reason < 0) {
    PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
    PetscCall(VecSetInf(x));
  }
  return 0;
}

// y = P⁻¹ r: y_p = S⁻¹ r_p, then y_u = A_u⁻¹ (r_u − Bᵀ y_p).
PetscErrorCode apply(PC pc, Vec r, Vec y) {
  Factorisation* f = nullptr;
  PetscCall(PCShellGetContext(pc, &f));
  FieldVectors& v = *f->v;
  PetscCall(v.read(r));
  PetscCall(v.write(y));
  PetscCall(inner_solve(pc, f->ksp_p, v.in_p, v.out_p));
  PetscCall(MatMult(f->Bt, v.out_p, v.w_u));
  PetscCall(VecAYPX(v.w_u, -1.0, v.in_u));  // r_u − Bᵀ y_p
  PetscCall(inner_solve(pc, f->ksp_u, v.w_u, v.out_u));
  PetscCall(v.end_read(r));
  return v.end_write(y);
}

// One V-cycle on M under the options' prefix: the defaults set in the options database
// (petsc_plugin.cpp's set_iterative) or PETSC_OPTIONS's. M is handed to hypre in
// hypre's format, PETSc's copy freed, when the preconditioner is hypre's; M is then the
// matrix the solver holds (the caller's reference to it, to keep or destroy).
std::string inner(const char* prefix, Mat& M, KSP& ksp) {
  FSI_TRY(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(M)), &ksp));
  FSI_TRY(KSPSetOptionsPrefix(ksp, prefix));
  FSI_TRY(KSPSetFromOptions(ksp));
  PC pc;
  FSI_TRY(KSPGetPC(ksp, &pc));
  PetscBool hypre = PETSC_FALSE;
  FSI_TRY(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCHYPRE, &hypre));
  if (hypre) {
    Mat converted = nullptr;
    FSI_TRY(MatConvert(M, MATHYPRE, MAT_INITIAL_MATRIX, &converted));
    FSI_TRY(MatDestroy(&M));
    M = converted;
  }
  FSI_TRY(KSPSetOperators(ksp, M, M));
  FSI_TRY(KSPSetUp(ksp));
  return "";
}

}  // namespace

std::string set_schur_factorisation(PC pc, Mat& A_u, Mat& S, Mat Bt, std::shared_ptr<FieldVectors> v) {
  FSI_TRY(PCSetType(pc, PCSHELL));
  auto* f = new Factorisation;
  FSI_TRY(PCShellSetContext(pc, f));
  FSI_TRY(PCShellSetDestroy(pc, destroy_factorisation));  // f freed with pc from here on
  FSI_TRY(PCShellSetApply(pc, apply));
  FSI_TRY(PCShellSetName(pc, "upper Schur factorisation [A_u B^T; 0 S], BoomerAMG on A_u and S_p"));
  FSI_TRY(PetscObjectReference(reinterpret_cast<PetscObject>(Bt)));
  f->Bt = Bt;
  // S's hierarchy first, A_u's next: PETSc's copy of each freed before the next is made.
  if (std::string e = inner("fluid_fieldsplit_p_", S, f->ksp_p); !e.empty()) return e;
  FSI_TRY(MatDestroy(&S));  // the solver holds it
  if (std::string e = inner("fluid_fieldsplit_u_", A_u, f->ksp_u); !e.empty()) return e;
  f->v = std::move(v);
  return "";
}

}  // namespace fsi
