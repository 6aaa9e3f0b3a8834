// The PETSc side of the fluid layer, a plugin: libfsicontact_petsc.so
// (petsc_plugin.cpp) links PETSc (Debian's libpetsc-real-dev: OpenMPI, MUMPS, hypre)
// and is loaded (dlopen) the first time a run asks for fluid.linear_solver =
// "petsc-mumps" or "petsc-iterative" (SPEC §13), so that the runs that do not, the
// default, neither load PETSc and its MPI nor start MPI (petsc_solver.hpp).
//
// Its solvers hold PETSc objects behind an opaque handle; every function reports
// PETSc's errors as text ("" when none), never as a C++ exception across the
// library's edge. On several MPI ranks (mpirun) every rank calls every function, each
// with its own block of rows (row_block) of the operator and the pressure mass matrix,
// which it alone assembled (StokesAssembler::share_rows); every rank gets the whole
// solution back.
#pragma once

#include <string>
#include <vector>

namespace fsi {

// Rows [first, last) of a square n × n matrix, compressed (row_start[0] = 0, columns
// 0-based and sorted in each row). The pattern of every call for one solver is the
// first call's (SparseDirectSolver checks it).
struct PetscCsr {
  int n = 0;
  int first = 0, last = 0;
  const int* row_start = nullptr;  // last − first + 1
  const int* column = nullptr;
  const double* value = nullptr;
  // On one rank: the arrays may be used in place (no copy), for they stay where they
  // are, with the values of the last set_operator, until the solver's next
  // set_operator or destroy. Otherwise, and on several ranks, they are copied.
  bool borrowed = false;
};

// This rank's rows of a square n × n matrix held by columns, compressed, in the
// caller's numbering: column j's entries are column_start[j] .. column_start[j + 1], in
// rows `row` (any order), of values `value`. The plugin's numbering is to[old] (from its
// inverse: from[to[i]] = i); only the rows whose number to[i] lies in this rank's block
// [first, last) are read.
struct PetscColumns {
  int n = 0;
  int first = 0, last = 0;
  const int* column_start = nullptr;  // n + 1
  const int* row = nullptr;
  const double* value = nullptr;
  const int* to = nullptr;    // n
  const int* from = nullptr;  // n
};

struct PetscSolverConfig {
  bool iterative = false;  // "petsc-iterative"; else MUMPS through PETSc
  bool symmetric = false;  // values symmetric: MUMPS LDLᵀ instead of LU
  double tol = 1e-10;      // relative to ‖b‖, the residual's own norm (iterative)
  int max_iterations = 1000;
  // The Krylov method (iterative): "gmres" (restart 100) or "bicgstab", whose memory
  // does not grow with the iterations (fluid.krylov).
  std::string krylov = "gmres";
  // Per unknown, 1 for the pressure's (the saddle point's second field), 0 for the
  // velocity's: the block preconditioner's split (iterative).
  std::vector<char> is_pressure;
};

struct PetscSolveReport {
  int iterations = 0;
  double residual = 0;            // ‖b − A x‖ / ‖b‖ at the end, computed anew (iterative)
  std::vector<double> history;    // the residual norm of every iteration, relative
  std::string reason;             // PETSc's converged or diverged reason
};

struct PetscPlugin {
  // Must equal kPetscPluginVersion: the loader refuses a plugin of another build.
  int version;
  // PetscInitialize (MPI too, if no one has), once per process; PETSc's error
  // handler set to return, its signal handlers off (the program has its own). Fills
  // the rank and the number of ranks of the run. "" or the error.
  std::string (*initialise)(int& rank, int& ranks);
  // This rank's block [first, last) of n unknowns: PETSc's even split, rank by rank.
  void (*row_block)(int n, int& first, int& last);
  // values[0..count) summed over the ranks, in place on every rank (MPI_Allreduce);
  // "" or the error.
  std::string (*sum_over_ranks)(double* values, int count);
  // The largest of every rank's `local` (a signal number, 0 for none), on every rank:
  // common/interrupt's agreement (agree_on_interrupts). An MPI error counts as SIGTERM.
  int (*largest_over_ranks)(int local);
  // A solver (null and `error` set if it cannot be made).
  void* (*create)(const PetscSolverConfig& config, std::string& error);
  // The operator's values (direct: copied unless borrowed; its first call fixes the
  // pattern). Iterative: split at once into its blocks (petsc_blocks.hpp), never held
  // whole, and A's arrays not read once this returns.
  std::string (*set_operator)(void* solver, const PetscCsr& A);
  // Iterative only: set_operator's, from this rank's rows held by columns in the
  // caller's numbering. Spares the caller a copy of its rows in PETSc's numbering (the
  // plugin's blocks are filled from its columns, read in PETSc's order).
  std::string (*set_operator_columns)(void* solver, const PetscColumns& A);
  // After set_operator: the factorisation (direct); nothing more (iterative). Apart
  // from finish_set_up so that the caller can free its rows first: the set-up is the
  // memory's peak.
  std::string (*set_up)(void* solver);
  // After set_up (iterative): the Schur preconditioner's matrix and the
  // preconditioner's set-up, from the blocks taken; the next solve does it if not
  // called. Nothing for MUMPS.
  std::string (*finish_set_up)(void* solver);
  // The pressure mass matrix M_w on the pressure unknowns, this rank's rows of it
  // (iterative), before set_operator: the Schur preconditioner of the next set-up
  // (only: M_w is freed once S_p is built) is then S_p = D − B diag(A)⁻¹ Bᵀ − M_w,
  // built from the operator by PETSc (without it, the same less M_w: PETSc's "selfp").
  std::string (*set_pressure_mass)(void* solver, const PetscCsr& M);
  // x with A x = b, both of the whole size: this rank's rows [first, last) of b are
  // read; x holds the initial guess if `warm` (iterative), the whole solution on return.
  std::string (*solve)(void* solver, const double* b, double* x, bool warm, PetscSolveReport& report);
  void (*destroy)(void* solver);
  // Frees the iterative solver's last set-up (split, hierarchies, S_p), which the next
  // set-up rebuilds anyway, before the caller builds the next pass's matrices; the
  // next set_pressure_mass or set_operator does it too. Nothing for MUMPS.
  std::string (*release)(void* solver);
};
inline constexpr int kPetscPluginVersion = 9;

}  // namespace fsi
