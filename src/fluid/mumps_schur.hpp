// A partial LDLᵀ factorisation of a symmetric indefinite matrix through MUMPS's Schur
// complement option: for A = [A_FF A_FΓ; A_ΓF A_ΓΓ] it eliminates the unknowns F and
// returns the dense S = A_ΓΓ − A_ΓF A_FF⁻¹ A_FΓ, and it reduces a right-hand side to Γ
// (condensation, y_Γ = b_Γ − A_ΓF A_FF⁻¹ b_F) and recovers x_F from x_Γ (expansion,
// x_F = A_FF⁻¹ (b_F − A_FΓ x_Γ)).
//
// The penalised Stokes solver uses it to factorise the part of the fluid that χ
// never reaches once per run (src/fluid/penalised_stokes.cpp, docs/performance.md).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

namespace fsi {

class MumpsSchur {
 public:
  MumpsSchur();
  ~MumpsSchur();
  MumpsSchur(const MumpsSchur&) = delete;
  MumpsSchur& operator=(const MumpsSchur&) = delete;

  // Analyses and factorises A (symmetric, compressed; both triangles stored or the
  // lower one only — the latter saves a copy of the values), with the
  // unknowns `gamma` (0-based, distinct, not empty) kept as the Schur complement.
  // `order`: the unknowns in a fill-reducing elimination order (a permutation), or
  // empty for METIS on A's pattern; Γ is eliminated last either way. Throws
  // SolverFailure if A has a non-finite entry, A_FF is singular or MUMPS fails
  // (condense() and expand() likewise for a non-finite b or x_Γ).
  void factorize(const Eigen::SparseMatrix<double>& A, const std::vector<int>& gamma,
                 const std::vector<int>& order = {});
  // S, symmetric, both triangles filled; rows and columns in the order of `gamma`.
  const Eigen::MatrixXd& schur() const { return S_; }
  // y_Γ for the right-hand side b (of A's size); b is kept for expand().
  Eigen::VectorXd condense(const Eigen::VectorXd& b);
  // The whole x with x_Γ as given and x_F = A_FF⁻¹ (b_F − A_FΓ x_Γ), b the vector
  // of the last condense(). (MUMPS's forward elimination serves one expansion; a
  // second one redoes it.)
  Eigen::VectorXd expand(const Eigen::VectorXd& x_gamma);
  // Frees the factors (MUMPS's whole instance) but keeps S: condense() and expand()
  // need a new factorize() first. For a large far field, whose factors are needed
  // only for the expansions, this lets a run hold S alone between them.
  void release();
  bool has_factors() const { return m_ != nullptr; }
  // Entries of the factors of A_FF (MUMPS INFOG(29)), the flops of the elimination,
  // and the memory MUMPS used for it (INFOG(22), MB), all of the last factorize().
  double factor_entries() const { return entries_; }
  double factor_flops() const { return flops_; }
  double factor_memory_mb() const { return memory_mb_; }

 private:
  struct Mumps;
  std::unique_ptr<Mumps> m_;
  Eigen::MatrixXd S_;
  Eigen::VectorXd b_;
  double entries_ = -1, flops_ = -1, memory_mb_ = -1;
  bool condensed_ = false, expanded_ = false;
};

}  // namespace fsi
