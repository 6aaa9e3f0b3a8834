// Inside the PETSc plugin: "petsc-iterative"'s preconditioner for the saddle point
// K = [A_u Bᵀ; B D], the upper block factorisation P = [A_u Bᵀ; 0 S] (Elman, Silvester,
// Wathen 2014, ch. 9; right preconditioning, so that the Krylov method converges on
// b − K x itself): P⁻¹ r = (A_u⁻¹ (r_u − Bᵀ y_p), y_p) with y_p = S⁻¹ r_p, each inverse
// one V-cycle of hypre's BoomerAMG, A_u's on the velocity block and S's on S_p
// (petsc_plugin.cpp's schur_preconditioner says which S_p).
//
// PETSc's field split applies the same P; this one holds fewer copies. The split kept
// its own copies of K's four blocks (0.38 kB a fluid triangle) while hypre held copies
// of A_u and S_p in its own format; here A_u and S_p are handed to hypre in its format
// (MATHYPRE) and PETSc's copies freed, and of the others only Bᵀ is kept, for the
// product (docs/performance.md, "The memory a triangle, continued").
//
// The inner solvers keep the split's option prefixes, fluid_fieldsplit_u_ and
// fluid_fieldsplit_p_, so that PETSC_OPTIONS reaches them as before (e.g.
// "-fluid_fieldsplit_u_pc_type gamg": a preconditioner other than hypre is then given
// PETSc's own matrices).
#pragma once

#include <petscksp.h>

#include <memory>
#include <string>

#include "fluid/petsc_blocks.hpp"
#include "fluid/petsc_field_vectors.hpp"

namespace fsi {

// pc becomes P⁻¹ for the operator K split by its fields, with K's velocity block A_u
// (taken; on return the matrix the inner solver holds, hypre's copy when hypre's: the
// caller's reference, which the block operator shares), the Schur complement's
// preconditioning matrix S (taken and freed once hypre holds it), K's (u, p) block Bt
// (referenced) and the fields' work space v (shared with the block operator). Both
// hierarchies are built here; they are freed with pc. "" or the error.
std::string set_schur_factorisation(PC pc, Mat& A_u, Mat& S, Mat Bt, std::shared_ptr<FieldVectors> v);

}  // namespace fsi
