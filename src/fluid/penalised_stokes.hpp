// Steady Stokes on the fixed mesh of D with the structure as a penalty (paper §4,
// eqs. 25–26, SPEC §3):
//     ∫ 2μ ε(v):ε(w) − ∫ (div w) p + (1/ε) ∫ χ v·w = ∫ f·w (+ ∫_{Γ_N} h·w),
//     −∫ (div v) q = 0,
// mini element with condensed bubbles. The velocity is prescribed on the Dirichlet
// labels; the rest of the boundary is natural (traction h, zero by default). There
// is no mean-pressure constraint: with a traction boundary the pressure is unique.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "fluid/mini_element.hpp"
#include "fluid/region_schur.hpp"
#include "fluid/sparse_solver.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

using VectorField = std::function<Point(const Point&)>;

struct FluidBoundaryConditions {
  std::vector<int> dirichlet_labels;                 // velocity prescribed here
  VectorField g = [](const Point&) { return Point(0, 0); };  // its value
  // A value of its own on some of those labels (the inflow on Σ4): boundary
  // conditions belong to labels, never to coordinates. At a vertex on two labels the
  // later label in dirichlet_labels decides.
  std::vector<std::pair<int, VectorField>> dirichlet_values;
  std::vector<std::pair<int, VectorField>> tractions;  // σ n = h on these labels
};

// The discrete fluid state: P1 parts at the vertices, bubble coefficients per triangle.
struct FluidSolution {
  Eigen::VectorXd v1, v2, p;
  Eigen::Matrix2Xd bubble;
  // Null: the fields are the solution everywhere. Otherwise only on the triangles t
  // with (*exact_on)[t] (a near-only solve, PenalisedStokes::solve(true)); FluidField
  // refuses to evaluate elsewhere (FieldNotComputed).
  const std::vector<char>* exact_on = nullptr;
};

struct FluidTiming {
  double assembly = 0, factorization = 0, solve = 0;
  double analysis = 0;  // the one symbolic analysis, part of `factorization`
  int analyses = 0, factorizations = 0, reused = 0;  // reused: χ unchanged, previous solution returned
  // Substructured solves (RegionSchurSolver): the far-field factorisations (one per
  // near region, part of `factorization`) and the expansions (part of `solve`).
  double far_factorization = 0, expansion = 0;
  int regions = 0;
  int far_refactorizations = 0;  // expansions that refactorised a released far field
};

// How solve() factorises: `schur` keeps the far field's factorisation and its Schur
// complement for the whole run and refactorises only the region χ can reach
// (RegionSchurSolver); `whole` refactorises all of K after every χ change.
enum class FluidFactorization { schur, whole };

class PenalisedStokes {
 public:
  PenalisedStokes(const Mesh& mesh, double mu, double eps, const VectorField& f,
                  const FluidBoundaryConditions& bc, const std::string& solver = kDefaultSparseSolver);

  // χ per triangle (0 outside the structure, 1 inside; fractions allowed).
  void set_chi(const Eigen::VectorXd& chi);
  // A new penalty ε (the pattern and its symbolic analysis are kept).
  void set_eps(double eps);
  void set_factorization(FluidFactorization f) { factorization_ = f; }
  FluidFactorization factorization() const { return factorization_; }
  // Far fields whose factorisation needs more than this (MB, MUMPS's estimate) are
  // not kept: each expansion refactorises them (RegionSchurSolver). INFINITY: keep all.
  void set_far_factor_budget(double mb) { far_factor_budget_mb_ = mb; }
  // Where χ is expected to go (per triangle, as χ; empty: nowhere known): the first
  // near region also covers this support, so that a structure moving there does not
  // force a second far-field factorisation. The coupling predicts it from the
  // structure under its applied loads alone. A region kept from before (see reset())
  // that does not cover the hint is dropped, so that the next one does.
  void set_region_hint(Eigen::VectorXd chi_hint);
  // The substructured solver in use (null before the first substructured solve).
  const RegionSchurSolver* region() const { return region_.get(); }
  // Forget the last solution (the next solve() refactorises), e.g. for a new run.
  // The near region and its far-field factorisation are kept (χ = 0 there, so they
  // hold for any ε): a sweep's next row reuses them if its hint lies inside.
  void reset();
  const Eigen::VectorXd& chi() const { return chi_; }
  // Solves for the current χ; if χ did not change since the last solve, returns
  // the previous solution without refactorising. near_only: with the substructured
  // factorisation, the fields may be left exact only on the near region (the far
  // field's expansion deferred until complete() or a solve() that needs it).
  const FluidSolution& solve(bool near_only = false);
  // The last solution made exact everywhere (the deferred expansion, if any). One
  // exception: if the solve after a change of near region fails, the solution before
  // it stays exact near the structure only (FluidSolution::exact_on).
  const FluidSolution& complete();

  // The last successful solution and the χ it was computed with (after a failed
  // solve: the one before). Empty before the first success.
  bool has_solution() const { return solved_once_; }
  const FluidSolution& last_solution() const { return solution_; }
  const Eigen::VectorXd& last_solution_chi() const { return solved_chi_; }

  const Mesh& mesh() const { return mesh_; }
  double mu() const { return mu_; }
  double eps() const { return eps_; }
  int unknowns() const { return static_cast<int>(free_.size()); }
  long nonzeros() const { return nonzeros_; }  // of the whole K
  const FluidTiming& timing() const { return timing_; }
  std::string solver_name() const;
  // Assembles K and rhs for the current χ over all triangles, as solve() does after
  // a reset or a new ε, without factorising (for benchmarks and tests).
  void assemble_full();
  // The condensed system K x = rhs on the free dofs as last assembled (by solve()
  // or assemble_full()).
  const Eigen::SparseMatrix<double>& matrix() const { return K_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  void assemble();
  void build_whole_pattern();
  void add_element(int t, double chi, double sign);
  ElementSystem element_system(int t) const;
  std::array<int, 9> element_dofs(int t) const;
  Eigen::VectorXd solve_whole();
  bool solve_substructured();
  bool near_region_covers(const Eigen::VectorXd& chi) const;
  void drop_region();
  const std::vector<int>& dof_rank();
  void build_near_region();
  void settle_pending_expansion();
  void recover_bubbles(const Eigen::VectorXd& z, const Eigen::VectorXd& chi);
  void recover_bubble(int t, const Eigen::VectorXd& z, double chi);
  void store(const Eigen::VectorXd& x, const Eigen::VectorXd& chi);

  const Mesh& mesh_;
  double mu_, eps_;
  std::vector<ElementLoad> loads_;
  std::vector<P1Triangle> geometry_;
  Eigen::VectorXd chi_;
  Eigen::VectorXd z_fixed_;            // prescribed values of all 3nv dofs (0 where free)
  std::vector<int> free_index_;        // full dof → reduced index, −1 if prescribed
  std::vector<int> free_;              // reduced index → full dof
  std::vector<int> slot_;              // 81 per triangle: position in K_.valuePtr(), −1 if not free-free
  long nonzeros_ = 0;                  // of the whole K (whose pattern is built only if needed)
  std::vector<int> dof_rank_;          // reduced dof → position in a METIS order (vertex graph)
  FluidFactorization factorization_ = FluidFactorization::whole;
  std::unique_ptr<RegionSchurSolver> region_;
  // Where the last solution is exact when its region was replaced before it was
  // completed (that region's far factors released: completing it would have cost a
  // far-field factorisation, and only a failed solve right after would need it).
  std::vector<char> stale_mask_;
  double far_factor_budget_mb_ = INFINITY;
  Eigen::VectorXd region_hint_;       // see set_region_hint
  double region_margin_ = 0;           // the near region: χ's support's box grown by this
  std::vector<char> region_interior_vertex_;  // vertices whose triangles are all near
  bool region_too_large_ = false;      // the near region would be most of D: solve whole
  bool pending_expansion_ = false;     // solution_ is exact on the near region only
  Eigen::VectorXd traction_load_;      // ∫ h·w on the reduced dofs
  Eigen::SparseMatrix<double> K_;
  Eigen::VectorXd rhs_;
  std::unique_ptr<SparseDirectSolver> solver_;
  bool analysed_ = false, solved_ = false, chi_changed_ = true, solved_once_ = false;
  bool assembled_ = false;
  Eigen::VectorXd assembled_chi_;  // χ of the values now in K_ and rhs_
  double assembled_eps_ = 0;
  int updates_since_full_ = 0;
  Eigen::VectorXd solved_chi_;
  FluidSolution solution_;
  FluidTiming timing_;
};

// Local dof k (0..8 = v1×3, v2×3, p×3) of triangle `tri` → full dof index.
inline int fluid_dof(const std::array<int, 3>& tri, int k, int nv) {
  return (k / 3) * nv + tri[k % 3];
}

}  // namespace fsi
