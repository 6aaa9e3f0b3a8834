#include "fluid/petsc_ksp_defaults.hpp"

#include <utility>

#include "fluid/petsc_try.hpp"

namespace fsi {
namespace {

std::string set_default(const char* name, const char* value) {
  PetscBool given = PETSC_FALSE;
  FSI_TRY(PetscOptionsHasName(nullptr, nullptr, name, &given));
  if (!given) FSI_TRY(PetscOptionsSetValue(nullptr, name, value));
  return "";
}

}  // namespace

// MUMPS's LU, or its LDLᵀ for symmetric values.
std::string set_direct(KSP ksp, bool symmetric) {
  PC pc;
  FSI_TRY(KSPGetPC(ksp, &pc));
  FSI_TRY(KSPSetType(ksp, KSPPREONLY));
  FSI_TRY(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU));
  FSI_TRY(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  return "";
}

// GMRES or BiCGStab, right-preconditioned (the residual they converge on is b − A x
// itself), by the upper block factorisation of the Schur split. GMRES(100) keeps up to
// 101 vectors: 0.84 KB a triangle at h = 0.0025, a fifth of the run's memory; BiCGStab
// keeps 7 at the cost of two preconditioner applications an iteration
// (docs/performance.md, "The memory a triangle").
std::string set_iterative(KSP ksp, const std::string& krylov) {
  if (krylov == "bicgstab") {
    FSI_TRY(KSPSetType(ksp, KSPBCGS));
  } else if (krylov == "gmres") {
    FSI_TRY(KSPSetType(ksp, KSPGMRES));
    FSI_TRY(KSPGMRESSetRestart(ksp, 100));
  } else {
    return "unknown Krylov method \"" + krylov + "\"";
  }
  FSI_TRY(KSPSetPCSide(ksp, PC_RIGHT));
  // The preconditioner (petsc_schur.hpp) is made at each set-up, and its inner solvers
  // with it: their defaults go to the options database, which they read then, under
  // the prefixes of PETSc's field split (kept for PETSC_OPTIONS). The velocity block couples its two
  // components (the symmetric gradient) and holds the penalty's mass: BoomerAMG's
  // strength threshold 0.7 instead of its 2D default 0.25 took GMRES from 215 to 65
  // iterations at h = 0.005 and keeps them at 61-71 from h = 0.02 to 0.0025 (the
  // §7.2 box, bench/petsc_study.py; docs/performance.md "PETSc"). Aggressive
  // coarsening on the first level of both (agg_nl 1) trades more iterations for
  // lighter hierarchies: with BiCGStab at 5.6 M unknowns 89 against 81 iterations but
  // 210 against 337 s and 10.7 against 11.7 GB; on the 9 424-triangle §7.2 case the
  // same time (docs/performance.md, "The memory a triangle"). Both smooth by hypre's
  // Chebyshev polynomial (degree 2, on D^-1/2 A D^-1/2) instead of its hybrid symmetric
  // Gauss-Seidel: matrix-vector products, which stream and split across ranks, where
  // Gauss-Seidel runs row after row. At 930 681 triangles (h = 0.001) the Krylov solve
  // took 30.4 -> 22.5 s on one rank and 19.3 -> 15.2 s on two (medians of four
  // interleaved rounds), with 106 -> 107 and 111 -> 113 GMRES iterations; from h = 0.02
  // to 0.0025 and ε = 1e-3 to 1e-7, GMRES's iterations changed by -11 to +5 % and
  // BiCGStab's by -6 to +18 % (docs/performance.md, "Chebyshev smoothing").
  const std::pair<const char*, const char*> inner[] = {
      {"-fluid_fieldsplit_u_ksp_type", "preonly"},
      {"-fluid_fieldsplit_u_pc_type", "hypre"},
      {"-fluid_fieldsplit_u_pc_hypre_type", "boomeramg"},
      {"-fluid_fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.7"},
      {"-fluid_fieldsplit_u_pc_hypre_boomeramg_agg_nl", "1"},
      {"-fluid_fieldsplit_u_pc_hypre_boomeramg_relax_type_all", "Chebyshev"},
      {"-fluid_fieldsplit_p_ksp_type", "preonly"},
      {"-fluid_fieldsplit_p_pc_type", "hypre"},
      {"-fluid_fieldsplit_p_pc_hypre_type", "boomeramg"},
      {"-fluid_fieldsplit_p_pc_hypre_boomeramg_agg_nl", "1"},
      {"-fluid_fieldsplit_p_pc_hypre_boomeramg_relax_type_all", "Chebyshev"}};
  for (const auto& [name, value] : inner)
    if (std::string e = set_default(name, value); !e.empty()) return e;
  return "";
}

}  // namespace fsi
