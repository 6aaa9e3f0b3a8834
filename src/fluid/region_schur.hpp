// The penalised Stokes system solved by substructuring: the triangles χ can reach
// (the "near" region, around the structure) are kept apart from the rest (the far
// field, where χ = 0 in every fixed-point iteration). With Γ the unknowns shared by
// both parts, F the other far-field unknowns and I the other near unknowns,
//
//     K = [K_FF  K_FΓ      0   ]      far field: assembled and factorised once, with
//         [K_ΓF  K_ΓΓ(χ)  K_ΓI(χ)]    its Schur complement S = K_ΓΓ^far − K_ΓF K_FF⁻¹ K_FΓ
//         [0     K_IΓ(χ)  K_II(χ)]    (MumpsSchur);
//
// per χ only the near system M(χ) = [S + K_ΓΓ^near(χ)  K_ΓI(χ); K_IΓ(χ)  K_II(χ)] is
// assembled and factorised (a few per cent of the unknowns), and x_F is recovered by
// the expansion. The solution is that of K x = b up to round-off (tested against the
// whole-matrix solve). docs/performance.md gives the cost against refactorising K.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fluid/mini_element.hpp"
#include "fluid/mumps_schur.hpp"
#include "fluid/sparse_solver.hpp"

namespace fsi {

// A triangle's contribution: its 9 unknowns (reduced indices; −1 where prescribed,
// whose values are already lifted into F), the condensed matrix and load.
struct ElementSystem {
  std::array<int, 9> dof;
  Matrix9d K;
  Vector9d F;
};
using ElementFunction = std::function<ElementSystem(int t)>;
using ElementDofs = std::function<std::array<int, 9>(int t)>;  // the dof part alone
// rank[d]: the position of unknown d in a fill-reducing order of all unknowns; asked
// for once the far field is assembled (it may be computed on another thread meanwhile).
using DofRank = std::function<const std::vector<int>&()>;

// What PenalisedStokes reads to split its own timing (the far field's set-up it
// times itself).
struct RegionSchurTiming {
  double near_assembly = 0, near_factorization = 0;
  int far_refactorizations = 0;  // for expansions, after the far factors were released
};

class RegionSchurSolver {
 public:
  // n unknowns; near[t] marks the near triangles (at least one, not all); `load` is
  // a constant load on the unknowns added to the elements' (tractions); rank: the
  // order of the unknowns (none, or an empty one: METIS on the far field's matrix).
  // Assembles and factorises the far field with element(t) for the triangles not near.
  // far_factor_budget_mb: if the far field's factorisation takes more memory than
  // this (MUMPS's INFOG(22), MB), its factors are released once S and the condensed
  // load are known, and each expansion refactorises it (after releasing the near
  // factors): a fixed-point loop then holds S and the near factors only, and the
  // largest run needs about half the memory for one more far-field factorisation.
  RegionSchurSolver(int n, const std::vector<char>& near, const ElementDofs& dofs,
                    const ElementFunction& element, const Eigen::VectorXd& load,
                    const DofRank& rank = {}, const std::string& near_solver = kDefaultSparseSolver,
                    double far_factor_budget_mb = INFINITY);

  // x with K x = b, the near triangles assembled with element(t) now, in two steps.
  // solve_near: x on the near unknowns only (x_near[k] is unknown near_dofs()[k]),
  // the expansion to the far field deferred; checks the near system's residual.
  // expand: the whole x for the last solve_near, with the whole system's residual
  // check. Both throw SolverFailure if a factorisation fails or the residual
  // ‖Kx − b‖ exceeds 1e-8 ‖b‖ (a nearly singular system). A coupling step needs the
  // fields only where the structure is, so it can skip the expansion (a solve with
  // the far factors).
  const Eigen::VectorXd& solve_near(const ElementFunction& element);
  Eigen::VectorXd expand();
  // A new load, the far field's operator perhaps unchanged (a time step's history, an
  // inflow that changes in time): the far elements assembled again with element(t)
  // and `load`. If the far matrix is the factorised one, value for value, the new load
  // is condensed (one forward solve with the far factors) and true returned; if it
  // changed, or the far factors were released, false: the region must be built again.
  // The last solve_near() is no longer expandable.
  bool refresh_far_load(const ElementFunction& element, const Eigen::VectorXd& load);
  const std::vector<int>& near_dofs() const { return near_dofs_; }
  const std::vector<int>& near_triangles() const { return near_triangles_; }
  const std::vector<char>& near_mask() const { return near_; }

  int interface_unknowns() const { return static_cast<int>(gamma_.size()); }
  int near_unknowns() const { return static_cast<int>(near_dofs_.size()); }
  const RegionSchurTiming& timing() const { return timing_; }
  // Whether the far factors are kept between expansions (see the constructor).
  bool keeps_far_factors() const { return keep_far_; }
  // MUMPS's memory for the far field's factorisation (INFOG(22), MB).
  double far_factor_mb() const { return far_.factor_memory_mb(); }

 private:
  // The constructor's steps, in this order.
  // Fills near_triangles_ and far_triangles_; throws if either is empty.
  void split_triangles(const std::vector<char>& near);
  // Fills far_dofs_, near_dofs_ and gamma_; throws if Γ is empty.
  void split_unknowns(const std::vector<char>& near, const ElementDofs& dofs);
  // K_far_ (lower triangle) and b_far_, the load included.
  void assemble_far_field(const ElementDofs& dofs, const ElementFunction& element, const Eigen::VectorXd& load);
  // S and y_Γ; the far factors released if over the budget.
  void factorize_far_field(double far_factor_budget_mb);
  // near_local_, M_'s pattern and load_near_.
  void set_up_near_system(const ElementDofs& dofs, const Eigen::VectorXd& load);
  std::unique_ptr<SparseDirectSolver> make_near_solver() const;

  std::vector<char> near_;
  std::vector<int> near_triangles_, far_triangles_;
  std::vector<int> far_dofs_;   // far local → reduced (F then Γ)
  std::vector<int> near_dofs_;  // near local → reduced (Γ then I)
  std::vector<int> near_local_;  // reduced → near local, −1 if far only
  std::vector<int> far_local_;   // reduced → far local, −1 if near only
  std::vector<int> gamma_;      // Γ's far-local indices, in the order of the near-local 0..|Γ|−1
  std::vector<int> far_order_, near_order_;  // fill-reducing orders (empty: the solver's own)
  std::string near_solver_name_;
  bool keep_far_ = true;
  Eigen::SparseMatrix<double> K_far_, M_;
  Eigen::VectorXd b_far_, load_near_, y_gamma_;
  Eigen::VectorXd x_near_, b_near_;  // of the last solve_near
  bool solved_near_ = false;
  MumpsSchur far_;
  std::unique_ptr<SparseDirectSolver> near_solver_;
  RegionSchurTiming timing_;
  int n_;
};

}  // namespace fsi
