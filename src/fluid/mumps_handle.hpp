// One sequential MUMPS instance, by default for a symmetric indefinite matrix (SYM = 2:
// LDLᵀ with threshold 1×1/2×2 pivoting; SYM = 0, LU, for Navier–Stokes): its set-up and release, the calls and their errors,
// and the numeric factorisation that grows the workspace when pivoting needs more.
// Shared by MumpsSolver (src/fluid/sparse_solver.cpp) and MumpsSchur.
#pragma once

#include <dmumps_c.h>

#include <memory>
#include <string>

namespace fsi {

// What MUMPS's INFO(1) < 0 (with INFO(2)) means, in words a user can act on, the
// codes kept in brackets for experts: "the matrix is numerically singular (12
// pivots eliminated) [INFO(1) = -10, INFO(2) = 12]". After the MUMPS 5 users' guide,
// section "Error diagnostics"; codes a caller of this sequential, centralised,
// assembled interface cannot meet get the bracket alone.
std::string mumps_error_words(int info1, int info2);

class MumpsHandle {
 public:
  // `who` starts every error message, e.g. "mumps-metis: MUMPS ". sym: MUMPS's SYM,
  // 2 symmetric indefinite (LDLᵀ, the lower triangle given), 0 unsymmetric (LU, all entries).
  explicit MumpsHandle(std::string who, int sym = 2);
  ~MumpsHandle();
  MumpsHandle(const MumpsHandle&) = delete;
  MumpsHandle& operator=(const MumpsHandle&) = delete;

  DMUMPS_STRUC_C& id() { return id_; }
  const DMUMPS_STRUC_C& id() const { return id_; }
  MUMPS_INT& icntl(int i) { return id_.icntl[i - 1]; }  // 1-based, as in the MUMPS guide

  // Runs job; SolverFailure if MUMPS reports an error.
  void call(int job, const char* phase);
  // SolverFailure if the last call reported an error.
  void check(const char* phase) const;
  // Job 2, retried with twice the workspace margin (ICNTL(14)) when pivoting delayed
  // pivots past the analysis's estimate, up to 4 times. Returns INFO(1) unchecked,
  // so that the caller can word the singular case (−10) for its matrix.
  int factorize_numeric();
  // From now on the factorisation's main workspace S (its fronts and factors) is
  // this handle's own array (MUMPS's WK_USER), sized from the analysis's estimate
  // INFO(8) and kept from one factorisation to the next. MUMPS otherwise allocates
  // and frees those hundreds of MB at every factorisation, and the kernel maps and
  // zeroes every page again: a Newton solve refactorises 5 times and more.
  void keep_workspace() { keep_workspace_ = true; }

 private:
  std::string who_;
  bool keep_workspace_ = false;
  std::unique_ptr<double[]> workspace_;  // WK_USER while keep_workspace_
  std::size_t workspace_size_ = 0;
  DMUMPS_STRUC_C id_{};
  bool initialised_ = false;
};

}  // namespace fsi
