// Inside the PETSc plugin: the solvers' methods and their defaults. The defaults are set
// on the objects before KSPSetFromOptions, and the inner solvers' in PETSc's options
// database unless given there, so that PETSC_OPTIONS can change any of them: under the
// prefix "fluid_" for the iterative solver (e.g. "-fluid_ksp_monitor",
// "-fluid_fieldsplit_u_pc_type gamg"), "fluid_direct_" for MUMPS.
#pragma once

#include <petscksp.h>

#include <string>

namespace fsi {

// MUMPS's LU, or its LDLᵀ for symmetric values. "" or the error.
std::string set_direct(KSP ksp, bool symmetric);
// "gmres" or "bicgstab", right-preconditioned, and the inner solvers' defaults.
std::string set_iterative(KSP ksp, const std::string& krylov);

}  // namespace fsi
