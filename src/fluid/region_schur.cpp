#include "fluid/region_schur.hpp"

#include <algorithm>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "common/timer.hpp"

namespace fsi {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The pattern of the matrix assembled from `triangles` on the unknowns local[·]
// (−1: not in this matrix), both triangles stored (or, if `lower`, the lower one
// only), rows sorted; the first `dense` local unknowns are coupled to each other as
// well (room for a dense block). Built column by column from the dof–triangle
// incidence: no triplet list, which at hF = 0.0025 would hold 12 million entries.
SparseMatrix element_pattern(int n, const std::vector<int>& triangles, const std::vector<int>& local,
                             const ElementDofs& dofs, int dense, bool lower = false) {
  std::vector<int> start(n + 1, 0), incident;
  std::vector<std::array<int, 9>> element_dofs(triangles.size());
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const std::array<int, 9> d = dofs(triangles[e]);
    for (int k = 0; k < 9; ++k) element_dofs[e][k] = d[k] < 0 ? -1 : local[d[k]];
    for (int l : element_dofs[e])
      if (l >= 0) ++start[l + 1];
  }
  for (int j = 0; j < n; ++j) start[j + 1] += start[j];
  incident.resize(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < triangles.size(); ++e)
    for (int l : element_dofs[e])
      if (l >= 0) incident[fill[l]++] = static_cast<int>(e);

  std::vector<int> outer(n + 1, 0), inner, column, seen(n, -1);
  for (int j = 0; j < n; ++j) {
    column.clear();
    if (j < dense)
      for (int i = 0; i < dense; ++i) column.push_back(i), seen[i] = j;
    for (int k = start[j]; k < start[j + 1]; ++k)
      for (int l : element_dofs[incident[k]])
        if (l >= (lower ? j : 0) && seen[l] != j) column.push_back(l), seen[l] = j;
    std::sort(column.begin(), column.end());
    inner.insert(inner.end(), column.begin(), column.end());
    outer[j + 1] = static_cast<int>(inner.size());
  }
  SparseMatrix A(n, n);
  A.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
  std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), 0.0);
  return A;
}

// Adds an element to A (pattern from element_pattern; `lower`: its lower triangle
// only) and to b, unknowns mapped by local.
void add_element(SparseMatrix& A, Eigen::VectorXd& b, const ElementSystem& e, const std::vector<int>& local,
                 bool lower = false) {
  std::array<int, 9> l;
  for (int k = 0; k < 9; ++k) l[k] = e.dof[k] < 0 ? -1 : local[e.dof[k]];
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  double* values = A.valuePtr();
  for (int j = 0; j < 9; ++j) {
    if (l[j] < 0) continue;
    b[l[j]] += e.F[j];
    const int* first = inner + outer[l[j]];
    const int* last = inner + outer[l[j] + 1];
    for (int i = 0; i < 9; ++i)
      if (l[i] >= (lower ? l[j] : 0)) values[std::lower_bound(first, last, l[i]) - inner] += e.K(i, j);
  }
}

// The patterns' temporaries and a released factorisation leave the heap fragmented,
// and MUMPS's workspace, one large block, cannot reuse those pages: give them back
// before a far-field factorisation (row 9, hF = 0.0025: 10–80 MB of the peak).
void release_free_heap() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

// The unknowns by the regions whose triangles hold them: far only (F), both (Γ),
// near only (I).
struct UnknownRegions {
  std::vector<int> F, I, G;
};

UnknownRegions classify_unknowns(int n, const std::vector<char>& near, const ElementDofs& dofs) {
  const int nt = static_cast<int>(near.size());
  std::vector<char> in_far(n, 0), in_near(n, 0);
  for (int t = 0; t < nt; ++t)
    for (int d : dofs(t))
      if (d >= 0) (near[t] ? in_near : in_far)[d] = 1;
  UnknownRegions r;
  for (int d = 0; d < n; ++d) {
    if (in_far[d] && in_near[d]) r.G.push_back(d);
    else if (in_far[d]) r.F.push_back(d);
    else if (in_near[d]) r.I.push_back(d);
  }
  return r;
}

// The far unknowns (local indices into `far_dofs`) by their rank in the given order.
std::vector<int> far_order_by_rank(const std::vector<int>& far_dofs, const std::vector<int>& rank) {
  std::vector<int> order(far_dofs.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return rank[far_dofs[a]] < rank[far_dofs[b]]; });
  return order;
}

// M's Γ block is dense: Γ must be eliminated last (as the root of the elimination
// tree), or every Γ pivot fills I's rows. I in the given order, then Γ (the first
// ng near unknowns).
std::vector<int> near_order_by_rank(const std::vector<int>& near_dofs, const std::vector<int>& rank, int ng) {
  std::vector<int> order(near_dofs.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if ((a < ng) != (b < ng)) return b < ng;  // I before Γ
    return rank[near_dofs[a]] < rank[near_dofs[b]];
  });
  return order;
}

}  // namespace

RegionSchurSolver::RegionSchurSolver(int n, const std::vector<char>& near, const ElementDofs& dofs,
                                     const ElementFunction& element, const Eigen::VectorXd& load,
                                     const DofRank& dof_rank, const std::string& near_solver,
                                     double far_factor_budget_mb)
    : near_(near), near_solver_name_(near_solver), n_(n) {
  split_triangles(near);
  split_unknowns(near, dofs);
  assemble_far_field(dofs, element, load);
  // The order only now: the far field's pattern and elements (~15 ms at hF = 0.01)
  // overlap the METIS run computing it on the second core.
  static const std::vector<int> no_rank;
  const std::vector<int>& rank = dof_rank ? dof_rank() : no_rank;
  if (!rank.empty()) far_order_ = far_order_by_rank(far_dofs_, rank);
  factorize_far_field(far_factor_budget_mb);

  set_up_near_system(dofs, load);
  if (!rank.empty() && near_solver.rfind("mumps", 0) == 0)
    near_order_ = near_order_by_rank(near_dofs_, rank, static_cast<int>(gamma_.size()));
  near_solver_ = make_near_solver();
  near_solver_->analyze(M_);
}

void RegionSchurSolver::split_triangles(const std::vector<char>& near) {
  const int nt = static_cast<int>(near.size());
  for (int t = 0; t < nt; ++t) (near[t] ? near_triangles_ : far_triangles_).push_back(t);
  if (near_triangles_.empty() || far_triangles_.empty())
    throw std::invalid_argument("RegionSchurSolver: the near region must be neither empty nor everything");
}

void RegionSchurSolver::split_unknowns(const std::vector<char>& near, const ElementDofs& dofs) {
  const UnknownRegions r = classify_unknowns(n_, near, dofs);
  if (r.G.empty()) throw std::invalid_argument("RegionSchurSolver: the near region does not touch the far field");
  const int nf = static_cast<int>(r.F.size()), ng = static_cast<int>(r.G.size());
  far_dofs_ = r.F;
  far_dofs_.insert(far_dofs_.end(), r.G.begin(), r.G.end());
  near_dofs_ = r.G;
  near_dofs_.insert(near_dofs_.end(), r.I.begin(), r.I.end());
  gamma_.resize(ng);
  for (int k = 0; k < ng; ++k) gamma_[k] = nf + k;
}

void RegionSchurSolver::assemble_far_field(const ElementDofs& dofs, const ElementFunction& element,
                                           const Eigen::VectorXd& load) {
  far_local_.assign(n_, -1);
  for (std::size_t k = 0; k < far_dofs_.size(); ++k) far_local_[far_dofs_[k]] = static_cast<int>(k);
  // Only the lower triangle: MUMPS reads it in place, and the residual check
  // multiplies by its symmetric view (half the memory of the largest matrix).
  K_far_ = element_pattern(static_cast<int>(far_dofs_.size()), far_triangles_, far_local_, dofs, 0, /*lower=*/true);
  b_far_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(far_dofs_.size()));
  for (int t : far_triangles_) add_element(K_far_, b_far_, element(t), far_local_, /*lower=*/true);
  for (std::size_t k = 0; k < far_dofs_.size(); ++k) b_far_[static_cast<Eigen::Index>(k)] += load[far_dofs_[k]];
}

// The far elements are assembled in the constructor's order, so an unchanged operator
// gives the same values to the bit: comparing them decides, without trusting the
// caller to know which of its terms reach the far field (a BDF step changes the load
// only, except at BDF2's first step, whose α changes the mass).
bool RegionSchurSolver::refresh_far_load(const ElementFunction& element, const Eigen::VectorXd& load) {
  solved_near_ = false;
  if (!keep_far_) return false;
  SparseMatrix K = K_far_;
  std::fill(K.valuePtr(), K.valuePtr() + K.nonZeros(), 0.0);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(b_far_.size());
  for (int t : far_triangles_) add_element(K, b, element(t), far_local_, /*lower=*/true);
  if (!std::equal(K.valuePtr(), K.valuePtr() + K.nonZeros(), K_far_.valuePtr())) return false;
  for (std::size_t k = 0; k < far_dofs_.size(); ++k) b[static_cast<Eigen::Index>(k)] += load[far_dofs_[k]];
  b_far_ = std::move(b);
  y_gamma_ = far_.condense(b_far_);
  const std::size_t ng = gamma_.size();
  for (std::size_t k = ng; k < near_dofs_.size(); ++k)  // the tractions, if they changed
    load_near_[static_cast<Eigen::Index>(k)] = load[near_dofs_[k]];
  return true;
}

void RegionSchurSolver::factorize_far_field(double far_factor_budget_mb) {
  release_free_heap();
  far_.factorize(K_far_, gamma_, far_order_);
  y_gamma_ = far_.condense(b_far_);
  keep_far_ = !(far_.factor_memory_mb() > far_factor_budget_mb);
  if (!keep_far_) {
    far_.release();
    release_free_heap();
  }
}

void RegionSchurSolver::set_up_near_system(const ElementDofs& dofs, const Eigen::VectorXd& load) {
  const int ng = static_cast<int>(gamma_.size());
  near_local_.assign(n_, -1);
  for (std::size_t k = 0; k < near_dofs_.size(); ++k) near_local_[near_dofs_[k]] = static_cast<int>(k);
  M_ = element_pattern(static_cast<int>(near_dofs_.size()), near_triangles_, near_local_, dofs, ng);
  load_near_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(near_dofs_.size()));
  for (std::size_t k = ng; k < near_dofs_.size(); ++k)  // Γ's load went to the far field
    load_near_[static_cast<Eigen::Index>(k)] = load[near_dofs_[k]];
}

std::unique_ptr<SparseDirectSolver> RegionSchurSolver::make_near_solver() const {
  return near_order_.empty() ? make_sparse_solver(near_solver_name_) : make_mumps_solver(near_order_);
}

const Eigen::VectorXd& RegionSchurSolver::solve_near(const ElementFunction& element) {
  const int ng = static_cast<int>(gamma_.size());
  solved_near_ = false;

  Stopwatch clock;
  // M = [S 0; 0 0] + the near elements; Γ's columns start with the dense block.
  std::fill(M_.valuePtr(), M_.valuePtr() + M_.nonZeros(), 0.0);
  const Eigen::MatrixXd& S = far_.schur();
  for (int j = 0; j < ng; ++j)
    std::copy(S.col(j).data(), S.col(j).data() + ng, M_.valuePtr() + M_.outerIndexPtr()[j]);
  b_near_ = load_near_;
  for (int t : near_triangles_) add_element(M_, b_near_, element(t), near_local_);
  Eigen::VectorXd rhs = b_near_;
  rhs.head(ng) += y_gamma_;
  timing_.near_assembly += clock.elapsed();

  clock = Stopwatch{};
  if (!near_solver_) {  // released for an expansion
    near_solver_ = make_near_solver();
    near_solver_->analyze(M_);
  }
  near_solver_->factorize(M_);
  timing_.near_factorization += clock.elapsed();
  x_near_ = near_solver_->solve(rhs);
  if (!x_near_.allFinite()) throw SolverFailure("the Stokes solve produced a non-finite value");
  const double residual = (M_ * x_near_ - rhs).norm(), scale = rhs.norm();
  if (!(residual <= 1e-8 * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned near the structure: relative "
                        "residual " + std::to_string(residual / scale) + " after the direct solve");
  solved_near_ = true;
  return x_near_;
}

Eigen::VectorXd RegionSchurSolver::expand() {
  if (!solved_near_) throw std::logic_error("RegionSchurSolver: expand() without a solve_near()");
  const int ng = static_cast<int>(gamma_.size());
  if (!far_.has_factors()) {
    // The far factors were released: refactorise (the near factors go first, so
    // that both are never held at once; the next solve_near() redoes them).
    near_solver_.reset();
    release_free_heap();
    far_.factorize(K_far_, gamma_, far_order_);
    far_.condense(b_far_);
    ++timing_.far_refactorizations;
  }
  const Eigen::VectorXd x_far = far_.expand(x_near_.head(ng));
  if (!keep_far_) {
    far_.release();
    release_free_heap();
  }

  // The residual of the whole system, K x − b = far part + near part (without S):
  // one product with each matrix, which catches a nearly singular system.
  const Eigen::MatrixXd& S = far_.schur();
  Eigen::VectorXd x(n_), r = Eigen::VectorXd::Zero(n_), b = Eigen::VectorXd::Zero(n_);
  for (std::size_t k = 0; k < far_dofs_.size(); ++k) x[far_dofs_[k]] = x_far[static_cast<Eigen::Index>(k)];
  for (std::size_t k = ng; k < near_dofs_.size(); ++k) x[near_dofs_[k]] = x_near_[static_cast<Eigen::Index>(k)];
  const Eigen::VectorXd r_far = K_far_.selfadjointView<Eigen::Lower>() * x_far - b_far_;
  Eigen::VectorXd r_near = M_ * x_near_ - b_near_;
  r_near.head(ng) -= S * x_near_.head(ng);
  for (std::size_t k = 0; k < far_dofs_.size(); ++k) {
    r[far_dofs_[k]] += r_far[static_cast<Eigen::Index>(k)];
    b[far_dofs_[k]] += b_far_[static_cast<Eigen::Index>(k)];
  }
  for (std::size_t k = 0; k < near_dofs_.size(); ++k) {
    r[near_dofs_[k]] += r_near[static_cast<Eigen::Index>(k)];
    b[near_dofs_[k]] += b_near_[static_cast<Eigen::Index>(k)];
  }
  const double residual = r.norm(), scale = b.norm();
  if (!(residual <= 1e-8 * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned: relative residual " +
                        std::to_string(residual / scale) + " after the substructured direct solve");
  return x;
}

}  // namespace fsi
