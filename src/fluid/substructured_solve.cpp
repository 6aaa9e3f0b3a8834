#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/timer.hpp"
#include "fluid/stokes_strategy.hpp"

namespace fsi {

SubstructuredSolve::SubstructuredSolve(StokesAssembler& assembler, const std::string& solver,
                                       FluidTiming& timing, FluidSolution& out,
                                       double far_factor_budget_mb)
    : assembler_(assembler),
      whole_(assembler, solver, timing, out),
      timing_(timing),
      out_(out),
      far_factor_budget_mb_(far_factor_budget_mb) {
  assembler_.order_in_background();
}

// Through RegionSchurSolver: the far field was factorised when the near region was
// chosen; per χ only the near region is, and the fields are updated there. The
// expansion to the far field is done only if `sampled` reaches beyond the region. A
// near region that would be most of D, or χ = 0 (nothing to substructure around):
// the whole solve. The background order (dof_rank()) is joined before anything else
// may run METIS (the whole solve's analysis, the structure's CHOLMOD: see
// metis_ordering): by the first near region once its far field is assembled, by a
// whole solve first.
void SubstructuredSolve::solve(const Eigen::VectorXd& chi, double eps, SampledTriangles sampled) {
  if (!too_large_ && (chi.array() != 0).any()) {
    if (!restored_mask_.empty()) {
      build_near_region(chi, eps, std::move(restored_mask_));
      restored_mask_.clear();
    }
    if (first_of_run_) {
      first_of_run_ = false;
      start_region(chi, eps);
    } else if (!region_ || !near_region_covers(chi)) {
      build_near_region(chi, eps, region_mask(chi));
    }
    if (region_ && far_load_stale_) refresh_far_load(chi, eps);
    if (region_) {
      solve_near(chi, eps);
      if (!exact_on(sampled)) expand();
      return;
    }
  }
  assembler_.dof_rank();
  whole_.solve(chi, eps, sampled);
  pending_expansion_ = false;
}

// A run's first region is the one a run of its own would build (χ and the hint, the
// first margin); a region kept from the last run (a sweep's row) is reused only if it
// is that region, triangle for triangle: the row's numbers are then those of a
// separate run, bit for bit (another region rounds differently).
void SubstructuredSolve::start_region(const Eigen::VectorXd& chi, double eps) {
  if (continue_region_ && region_ && near_region_covers(chi)) return;
  margin_ = 0;
  too_large_ = false;
  std::vector<char> mask = region_mask(chi);
  if (too_large_) return;
  if (region_ && region_->near_mask() == mask) return;
  build_near_region(chi, eps, std::move(mask));
}

void SubstructuredSolve::solve_near(const Eigen::VectorXd& chi, double eps) {
  const RegionSchurTiming before = region_->timing();
  Stopwatch clock;
  const Eigen::VectorXd& x_near =
      region_->solve_near([&](int t) { return assembler_.element_system(t, chi[t] / eps); });
  const double total = clock.elapsed();
  const RegionSchurTiming& after = region_->timing();
  const double assembly = after.near_assembly - before.near_assembly;
  const double factorization = after.near_factorization - before.near_factorization;
  timing_.assembly += assembly;
  timing_.factorization += factorization;
  ++timing_.factorizations;

  clock = Stopwatch{};
  if (out_.v1.size() != assembler_.mesh().num_vertices()) assembler_.prescribed_fields(out_);  // nothing yet
  assembler_.scatter(region_->near_dofs(), x_near, out_);
  for (int t : region_->near_triangles()) assembler_.recover_bubble(t, chi[t] / eps, out_);
  out_.exact_on = &region_->near_mask();
  pending_expansion_ = true;
  pending_chi_ = chi;
  pending_eps_ = eps;
  timing_.solve += total - assembly - factorization + clock.elapsed();
}

// The deferred expansion of the last near solve to the far field.
void SubstructuredSolve::expand() {
  const Stopwatch clock;
  const int refactorized = region_->timing().far_refactorizations;
  assembler_.fields(region_->expand(), pending_chi_, pending_eps_, out_);
  timing_.far_refactorizations += region_->timing().far_refactorizations - refactorized;
  pending_expansion_ = false;
  const double elapsed = clock.elapsed();
  timing_.solve += elapsed;
  timing_.expansion += elapsed;
}

bool SubstructuredSolve::exact_on(SampledTriangles sampled) const {
  const std::vector<char>* mask = out_.exact_on;
  if (!mask) return true;
  if (!sampled) return false;
  return std::all_of(sampled->begin(), sampled->end(), [mask](int t) { return (*mask)[t] != 0; });
}

void SubstructuredSolve::extend(SampledTriangles sampled) {
  if (exact_on(sampled)) return;
  if (!pending_expansion_)
    throw SolverFailure("the fluid solution is exact near the structure only: the solve after its near region "
                        "was replaced failed, and that region's far-field factors were released");
  expand();
}

// Before the last solution's region or ε changes: its deferred expansion, if the
// far factors are at hand (one solve); otherwise (released: it would cost a far-field
// factorisation, for a solution only a failure right after would need) it stays
// exact on its near region only.
void SubstructuredSolve::settle() {
  if (!pending_expansion_) return;
  if (region_->keeps_far_factors()) {
    expand();
  } else {
    stale_mask_ = region_->near_mask();
    out_.exact_on = &stale_mask_;
    pending_expansion_ = false;
  }
}

void SubstructuredSolve::expect(Eigen::VectorXd chi_hint) {
  hint_ = std::move(chi_hint);
}

// The region and its far factors are kept: in a time run every step changes the
// load (the history, the inflow) and, after BDF2's first step, not the far operator.
void SubstructuredSolve::load_changed() {
  pending_expansion_ = false;
  continue_region_ = false;
  far_load_stale_ = region_ != nullptr;
}

// Stale until it succeeds: a failed condensation (a non-finite load) is tried again
// by the next solve, never skipped.
void SubstructuredSolve::refresh_far_load(const Eigen::VectorXd& chi, double eps) {
  const Stopwatch clock;
  const bool kept = region_->refresh_far_load([&](int t) { return assembler_.element_system(t, chi[t] / eps); },
                                              assembler_.traction_load());
  timing_.assembly += clock.elapsed();  // the far elements again, and one forward solve
  if (kept) far_load_stale_ = false;
  else build_near_region(chi, eps, std::vector<char>(region_->near_mask()));  // clears it
}

void SubstructuredSolve::near_changed() {
  if (!pending_expansion_) return;
  stale_mask_ = region_->near_mask();
  out_.exact_on = &stale_mask_;
  pending_expansion_ = false;
}

NearRegionState SubstructuredSolve::near_region_state() const {
  if (!region_) return {};
  return {region_->near_mask(), margin_};
}

// The next solve builds this region (with the problem it has then) instead of a run's
// first; the far field is assembled and factorised as the interrupted run's was.
void SubstructuredSolve::restore_near_region(NearRegionState state) {
  if (state.mask.empty()) return;
  region_.reset();
  pending_expansion_ = false;
  first_of_run_ = false;
  too_large_ = false;
  margin_ = state.margin;
  restored_mask_ = std::move(state.mask);
}

void SubstructuredSolve::new_run() {
  whole_.new_run();
  pending_expansion_ = false;
  hint_.resize(0);  // the last run's
  first_of_run_ = true;
  continue_region_ = false;
  too_large_ = false;  // decided again by the run's first region
}

// The support of chi and the triangles around it (sharing a vertex with it) inside
// the near region: the structure's vertices, where the coupling samples the fields,
// lie in those triangles, so a near-only solution serves it.
bool SubstructuredSolve::near_region_covers(const Eigen::VectorXd& chi) const {
  const Mesh& mesh = assembler_.mesh();
  for (int t = 0; t < mesh.num_triangles(); ++t)
    if (chi[t] != 0)
      for (int v : mesh.triangles[t])
        if (!interior_vertex_[v]) return false;
  return true;
}

// The near region: the triangles meeting the bounding box of χ's support grown by a
// margin, half the box's smaller side (at least 2 triangle sizes) at first and
// doubled whenever χ leaves the region, so that a structure moving across D costs
// a few far-field factorisations, not one per iteration. The first region covers the
// hint too. Sets too_large_ (and returns no region) if it would be most of D.
std::vector<char> SubstructuredSolve::region_mask(const Eigen::VectorXd& chi) {
  const Mesh& mesh = assembler_.mesh();
  Point lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  double h_max = 0;
  auto cover = [&](const Eigen::VectorXd& support) {  // grow [lo, hi] over its triangles
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      if (support[t] == 0) continue;
      const auto& tri = mesh.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const Point& a = mesh.vertices[tri[k]];
        lo = lo.cwiseMin(a), hi = hi.cwiseMax(a);
        h_max = std::max(h_max, (a - mesh.vertices[tri[(k + 1) % 3]]).norm());
      }
    }
  };
  cover(chi);
  const Point size = hi - lo;
  if (margin_ == 0 && hint_.size() == chi.size()) cover(hint_);  // the first region only
  margin_ = margin_ == 0 ? std::max(0.5 * size.minCoeff(), 2 * h_max) : 2 * margin_;
  lo.array() -= margin_, hi.array() += margin_;
  const int nt = mesh.num_triangles();
  std::vector<char> near(nt, 0);
  int count = 0;
  for (int t = 0; t < nt; ++t) {
    Point a(INFINITY, INFINITY), b(-INFINITY, -INFINITY);
    for (int v : mesh.triangles[t]) a = a.cwiseMin(mesh.vertices[v]), b = b.cwiseMax(mesh.vertices[v]);
    if ((a.array() <= hi.array()).all() && (b.array() >= lo.array()).all()) near[t] = 1, ++count;
  }
  if (2 * count > nt) {  // no gain over the whole factorisation
    too_large_ = true;
    return {};
  }
  return near;
}

void SubstructuredSolve::build_near_region(const Eigen::VectorXd& chi, double eps,
                                           std::vector<char> near) {
  settle();  // the last solution needs the old region
  region_.reset();
  far_load_stale_ = false;
  if (too_large_) return;
  const Stopwatch clock;
  const Mesh& mesh = assembler_.mesh();
  interior_vertex_.assign(mesh.num_vertices(), 1);  // all its triangles near
  for (int t = 0; t < mesh.num_triangles(); ++t)
    if (!near[t])
      for (int v : mesh.triangles[t]) interior_vertex_[v] = 0;
  region_ = std::make_unique<RegionSchurSolver>(
      assembler_.unknowns(), near, [this](int t) { return assembler_.element_dofs(t); },
      [&](int t) { return assembler_.element_system(t, chi[t] / eps); }, assembler_.traction_load(),
      [this]() -> const std::vector<int>& { return assembler_.dof_rank(); }, whole_.name(),
      far_factor_budget_mb_);
  const double elapsed = clock.elapsed();
  timing_.factorization += elapsed;
  timing_.far_factorization += elapsed;
  ++timing_.regions;
  ++timing_.analyses;
}

}  // namespace fsi
