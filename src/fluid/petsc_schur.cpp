#include "fluid/petsc_schur.hpp"

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

// What P⁻¹ holds between its applications.
struct Factorisation {
  KSP ksp_u = nullptr, ksp_p = nullptr;  // one V-cycle on A_u, one on S
  Mat Bt = nullptr;                      // K's (u, p) block
  Vec r_u = nullptr, r_p = nullptr, y_u = nullptr, y_p = nullptr;
  Vec whole = nullptr;                        // the layout the scatters start from
  VecScatter to_u = nullptr, to_p = nullptr;  // the whole vector to each field's
};

PetscErrorCode destroy_factorisation(PC pc) {
  Factorisation* f = nullptr;
  PetscCall(PCShellGetContext(pc, &f));
  if (!f) return 0;
  KSPDestroy(&f->ksp_u), KSPDestroy(&f->ksp_p), MatDestroy(&f->Bt);
  VecDestroy(&f->r_u), VecDestroy(&f->r_p), VecDestroy(&f->y_u), VecDestroy(&f->y_p);
  VecDestroy(&f->whole);
  VecScatterDestroy(&f->to_u), VecScatterDestroy(&f->to_p);
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
  PetscCall(VecScatterBegin(f->to_u, r, f->r_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(f->to_u, r, f->r_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterBegin(f->to_p, r, f->r_p, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(f->to_p, r, f->r_p, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(inner_solve(pc, f->ksp_p, f->r_p, f->y_p));
  PetscCall(MatMult(f->Bt, f->y_p, f->y_u));
  PetscCall(VecAYPX(f->y_u, -1.0, f->r_u));  // r_u − Bᵀ y_p
  PetscCall(inner_solve(pc, f->ksp_u, f->y_u, f->r_u));
  PetscCall(VecScatterBegin(f->to_u, f->r_u, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(f->to_u, f->r_u, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterBegin(f->to_p, f->y_p, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(f->to_p, f->y_p, y, INSERT_VALUES, SCATTER_REVERSE));
  return 0;
}

// One V-cycle on M (taken) under the options' prefix: the defaults set in the options
// database (petsc_plugin.cpp's set_iterative) or PETSC_OPTIONS's. M is handed to hypre
// in hypre's format, PETSc's copy freed, when the preconditioner is hypre's.
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
  FSI_TRY(MatDestroy(&M));  // the solver holds it
  FSI_TRY(KSPSetUp(ksp));
  return "";
}

std::string scatters(Factorisation& f, Mat K, IS u, IS p) {
  FSI_TRY(MatCreateVecs(f.Bt, &f.y_p, &f.y_u));
  FSI_TRY(VecDuplicate(f.y_u, &f.r_u));
  FSI_TRY(VecDuplicate(f.y_p, &f.r_p));
  FSI_TRY(MatCreateVecs(K, &f.whole, nullptr));
  FSI_TRY(VecScatterCreate(f.whole, u, f.r_u, nullptr, &f.to_u));
  FSI_TRY(VecScatterCreate(f.whole, p, f.r_p, nullptr, &f.to_p));
  return "";
}

}  // namespace

std::string set_schur_factorisation(PC pc, Mat K, IS u, IS p, Mat& S, Mat& Bt) {
  FSI_TRY(PCSetType(pc, PCSHELL));
  auto* f = new Factorisation;
  FSI_TRY(PCShellSetContext(pc, f));
  FSI_TRY(PCShellSetDestroy(pc, destroy_factorisation));  // f freed with pc from here on
  FSI_TRY(PCShellSetApply(pc, apply));
  FSI_TRY(PCShellSetName(pc, "upper Schur factorisation [A_u B^T; 0 S], BoomerAMG on A_u and S_p"));
  f->Bt = Bt;
  Bt = nullptr;
  // S's hierarchy first, A_u's next: PETSc's copy of each freed before the next is made.
  if (std::string e = inner("fluid_fieldsplit_p_", S, f->ksp_p); !e.empty()) return e;
  Mat A_u = nullptr;
  FSI_TRY(MatCreateSubMatrix(K, u, u, MAT_INITIAL_MATRIX, &A_u));
  if (std::string e = inner("fluid_fieldsplit_u_", A_u, f->ksp_u); !e.empty()) return e;
  return scatters(*f, K, u, p);
}

}  // namespace fsi
