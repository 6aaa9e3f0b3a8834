#include "fluid/penalised_stokes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/integration.hpp"
#include "common/errors.hpp"
#include "common/timer.hpp"

namespace fsi {
namespace {

// Two vertices are adjacent iff they share a triangle (a vertex is its own neighbour).
std::vector<std::vector<int>> vertex_adjacency(const Mesh& mesh) {
  std::vector<std::vector<int>> adjacent(mesh.num_vertices());
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      for (int b : tri) adjacent[a].push_back(b);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacent;
}

}  // namespace

PenalisedStokes::PenalisedStokes(const Mesh& mesh, double mu, double eps, const VectorField& f,
                                 const FluidBoundaryConditions& bc, const std::string& solver)
    : mesh_(mesh), mu_(mu), eps_(eps), solver_(make_sparse_solver(solver)) {
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();
  chi_ = Eigen::VectorXd::Zero(nt);
  geometry_.reserve(nt);
  loads_.reserve(nt);
  const TriangleRule rule = triangle_rule(6);  // bubble (degree 3) × smooth f
  for (int t = 0; t < nt; ++t) {
    geometry_.emplace_back(mesh, t);
    loads_.push_back(element_load(geometry_.back(), f, rule));
  }

  // Prescribed velocities on the Dirichlet labels.
  z_fixed_ = Eigen::VectorXd::Zero(3 * nv);
  std::vector<bool> fixed(3 * nv, false);
  for (int label : bc.dirichlet_labels) {
    const VectorField* value = &bc.g;
    for (const auto& [l, g] : bc.dirichlet_values)
      if (l == label) value = &g;
    for (int v : mesh.vertices_on(label)) {
      const Point g = (*value)(mesh.vertices[v]);
      for (int c = 0; c < 2; ++c) {
        fixed[c * nv + v] = true;
        z_fixed_[c * nv + v] = g[c];
      }
    }
  }
  free_index_.assign(3 * nv, -1);
  for (int d = 0; d < 3 * nv; ++d)
    if (!fixed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }

  // The number of nonzeros of the whole K (its pattern is built only when the whole
  // matrix is assembled: the substructured solve never needs it).
  {
    std::vector<std::vector<int>> adjacent = vertex_adjacency(mesh);
    for (int col = 0; col < static_cast<int>(free_.size()); ++col)
      for (int component = 0; component < 3; ++component)
        for (int i : adjacent[free_[col] % nv])
          if (free_index_[component * nv + i] >= 0) ++nonzeros_;
  }
  const int n = static_cast<int>(free_.size());

  // Natural boundary: ∫_{edge} h·w ds (bubbles vanish on edges).
  traction_load_ = Eigen::VectorXd::Zero(n);
  for (const auto& traction : bc.tractions) {
    const auto& h = traction.second;  // a structured binding: clang 14 cannot capture it
    integrate_on_edges(mesh, mesh.edges_on(traction.first), gauss_legendre(3), [&](const BoundaryEdge& e, const EdgePoint& q) {
      const Point hq = h(q.x) * q.ds;
      for (int c = 0; c < 2; ++c) {
        const int r0 = free_index_[c * nv + e.v[0]], r1 = free_index_[c * nv + e.v[1]];
        if (r0 >= 0) traction_load_[r0] += hq[c] * q.phi[0];
        if (r1 >= 0) traction_load_[r1] += hq[c] * q.phi[1];
      }
    });
  }
}

void PenalisedStokes::build_whole_pattern() {
  if (K_.rows() == static_cast<Eigen::Index>(free_.size()) && !slot_.empty()) return;
  const Mesh& mesh = mesh_;
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();
  // Sparsity pattern of the free–free block, built column by column from vertex
  // adjacency (two dofs couple iff their vertices share a triangle): no triplet list,
  // which at hF = 0.0025 would hold 12 million entries.
  const int n = static_cast<int>(free_.size());
  const std::vector<std::vector<int>> adjacent = vertex_adjacency(mesh);
  std::vector<int> outer_index(n + 1, 0), inner_index;
  for (int col = 0; col < n; ++col) {
    const int j = free_[col] % nv;
    for (int component = 0; component < 3; ++component)  // rows in increasing full index
      for (int i : adjacent[j]) {
        const int r = free_index_[component * nv + i];
        if (r >= 0) inner_index.push_back(r);
      }
    outer_index[col + 1] = static_cast<int>(inner_index.size());
  }
  K_ = Eigen::SparseMatrix<double>(n, n);
  K_.resizeNonZeros(static_cast<Eigen::Index>(inner_index.size()));
  std::copy(outer_index.begin(), outer_index.end(), K_.outerIndexPtr());
  std::copy(inner_index.begin(), inner_index.end(), K_.innerIndexPtr());
  std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
  slot_.assign(81 * static_cast<std::size_t>(nt), -1);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        const int r = free_index_[fluid_dof(mesh_.triangles[t], i, nv)];
        const int c = free_index_[fluid_dof(mesh_.triangles[t], j, nv)];
        if (r < 0 || c < 0) continue;
        const int* pos = std::lower_bound(inner + outer[c], inner + outer[c + 1], r);
        slot_[81 * static_cast<std::size_t>(t) + 9 * i + j] = static_cast<int>(pos - inner);
      }

}

void PenalisedStokes::set_chi(const Eigen::VectorXd& chi) {
  if (chi.size() != chi_.size()) throw std::invalid_argument("set_chi: one value per triangle");
  if (chi != chi_) {
    chi_ = chi;
    chi_changed_ = true;
  }
}

void PenalisedStokes::set_eps(double eps) {
  if (eps != eps_) {
    settle_pending_expansion();  // its bubbles need the old ε
    eps_ = eps;
    chi_changed_ = true;
  }
}

void PenalisedStokes::reset() {
  solved_ = solved_once_ = false;
  pending_expansion_ = false;
  assembled_ = false;
  chi_changed_ = true;
  chi_.setZero();
  timing_ = FluidTiming{};
  region_hint_.resize(0);                                       // the last run's
  if (!region_) region_margin_ = 0, region_too_large_ = false;  // nothing kept: start afresh
}

void PenalisedStokes::set_region_hint(Eigen::VectorXd chi_hint) {
  region_hint_ = std::move(chi_hint);
  // Only the first region covers the hint (build_near_region): a kept one that does
  // not would be grown around χ alone, the hint ignored (a sweep's rows).
  if (region_ && region_hint_.size() == chi_.size() && !near_region_covers(region_hint_))
    drop_region();
}

// Forgets the near region: the next substructured solve builds a first one.
void PenalisedStokes::drop_region() {
  settle_pending_expansion();  // the last solution needs the old region
  region_.reset();
  region_margin_ = 0;
  region_too_large_ = false;
}

// Adds sign × (the condensed element of triangle t with penalty χ/ε) to K and rhs.
void PenalisedStokes::add_element(int t, double chi, double sign) {
  const int nv = mesh_.num_vertices();
  const auto& tri = mesh_.triangles[t];
  const CondensedElement ce = condensed_mini_element(geometry_[t], mu_, chi / eps_, loads_[t]);
  const int* slots = &slot_[81 * static_cast<std::size_t>(t)];
  double* values = K_.valuePtr();
  for (int i = 0; i < 9; ++i) {
    const int r = free_index_[fluid_dof(tri, i, nv)];
    if (r < 0) continue;
    rhs_[r] += sign * ce.F[i];
    for (int j = 0; j < 9; ++j) {
      if (slots[9 * i + j] >= 0)
        values[slots[9 * i + j]] += sign * ce.K(i, j);
      else  // prescribed column: lift to the right-hand side
        rhs_[r] -= sign * ce.K(i, j) * z_fixed_[fluid_dof(tri, j, nv)];
    }
  }
}

void PenalisedStokes::assemble_full() {
  build_whole_pattern();
  std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
  rhs_ = traction_load_;
  for (int t = 0; t < mesh_.num_triangles(); ++t) add_element(t, chi_[t], 1.0);
  updates_since_full_ = 0;
  assembled_chi_ = chi_;
  assembled_eps_ = eps_;
  assembled_ = true;
}

// Between fixed-point iterations χ changes on a few triangles near the structure's
// outline: only those are re-assembled (old contribution out, new in). A full
// assembly is done after a reset or a new ε, when over a tenth of the triangles
// changed, and every 20 updates, which bounds the round-off of the differences.
void PenalisedStokes::assemble() {
  if (!assembled_ || assembled_eps_ != eps_ || updates_since_full_ >= 20) return assemble_full();
  std::vector<int> changed;
  for (int t = 0; t < mesh_.num_triangles(); ++t)
    if (chi_[t] != assembled_chi_[t]) changed.push_back(t);
  if (static_cast<int>(changed.size()) > mesh_.num_triangles() / 10) return assemble_full();
  for (int t : changed) {
    add_element(t, assembled_chi_[t], -1.0);
    add_element(t, chi_[t], 1.0);
  }
  ++updates_since_full_;
  assembled_chi_ = chi_;
}

std::string PenalisedStokes::solver_name() const {
  return factorization_ == FluidFactorization::schur ? solver_->name() + "+schur" : solver_->name();
}

const FluidSolution& PenalisedStokes::solve(bool near_only) {
  if (solved_ && !chi_changed_) {
    ++timing_.reused;
    return near_only ? solution_ : complete();
  }
  const bool substructure =
      factorization_ == FluidFactorization::schur && !region_too_large_ && (chi_.array() != 0).any();
  if (!substructure || !solve_substructured()) {
    const Eigen::VectorXd x = solve_whole();
    const Stopwatch clock;
    solved_ = false;  // until the new solution is complete
    store(x, chi_);
    pending_expansion_ = false;
    timing_.solve += clock.elapsed();
  }
  solved_ = solved_once_ = true;
  chi_changed_ = false;
  solved_chi_ = chi_;
  return near_only ? solution_ : complete();
}

const FluidSolution& PenalisedStokes::complete() {
  if (!pending_expansion_) return solution_;
  const Stopwatch clock;
  const int refactorized = region_->timing().far_refactorizations;
  store(region_->expand(), solved_chi_);  // the χ of the last solve
  timing_.far_refactorizations += region_->timing().far_refactorizations - refactorized;
  pending_expansion_ = false;
  const double elapsed = clock.elapsed();
  timing_.solve += elapsed;
  timing_.expansion += elapsed;
  return solution_;
}

// The fields from the reduced solution x (computed with χ = chi), everywhere.
void PenalisedStokes::store(const Eigen::VectorXd& x, const Eigen::VectorXd& chi) {
  Eigen::VectorXd z = z_fixed_;
  for (std::size_t k = 0; k < free_.size(); ++k) z[free_[k]] = x[static_cast<Eigen::Index>(k)];
  const int nv = mesh_.num_vertices();
  solution_.v1 = z.segment(0, nv);
  solution_.v2 = z.segment(nv, nv);
  solution_.p = z.segment(2 * nv, nv);
  recover_bubbles(z, chi);
  solution_.exact_on = nullptr;
}

// Assembles K (incrementally), factorises all of it, solves.
Eigen::VectorXd PenalisedStokes::solve_whole() {
  {
    const Stopwatch clock;
    assemble();
    timing_.assembly += clock.elapsed();
  }
  {
    const Stopwatch clock;
    if (!analysed_) {
      solver_->analyze(K_);
      analysed_ = true;
      timing_.analysis += clock.elapsed();
      ++timing_.analyses;
    }
    solver_->factorize(K_);
    timing_.factorization += clock.elapsed();
    ++timing_.factorizations;
  }
  const Stopwatch clock;
  Eigen::VectorXd x = solver_->solve(rhs_);
  if (!x.allFinite()) throw SolverFailure("the Stokes solve produced a non-finite value");
  // A nearly singular matrix can factorise without a zero pivot and give garbage:
  // one product with K (~1% of a factorisation) catches it. The solvers reach
  // ~1e-14 here, up to ε = 1e-7 (docs/performance.md); 1e-8 leaves a wide margin.
  const double residual = (K_ * x - rhs_).norm(), scale = rhs_.norm();
  if (!(residual <= 1e-8 * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned for " + solver_->name() +
                        ": relative residual " + std::to_string(residual / scale) + " after the direct solve");
  timing_.solve += clock.elapsed();
  return x;
}

// Through RegionSchurSolver: the far field was factorised when the near region was
// chosen; per χ only the near region is, and the fields are updated there (the
// expansion to the far field is left to complete()). False: the region would be
// most of D, solve whole.
bool PenalisedStokes::solve_substructured() {
  if (!region_ || !near_region_covers(chi_)) {
    build_near_region();
    if (!region_) return false;
  }
  const RegionSchurTiming before = region_->timing();
  Stopwatch clock;
  const Eigen::VectorXd& x_near = region_->solve_near([this](int t) { return element_system(t); });
  const double total = clock.elapsed();
  const RegionSchurTiming& after = region_->timing();
  const double assembly = after.near_assembly - before.near_assembly;
  const double factorization = after.near_factorization - before.near_factorization;
  timing_.assembly += assembly;
  timing_.factorization += factorization;
  ++timing_.factorizations;

  clock = Stopwatch{};
  solved_ = false;  // until the new solution is stored
  const int nv = mesh_.num_vertices();
  if (solution_.v1.size() != nv) {  // nothing yet: the prescribed values, zero elsewhere
    solution_.v1 = z_fixed_.segment(0, nv);
    solution_.v2 = z_fixed_.segment(nv, nv);
    solution_.p = z_fixed_.segment(2 * nv, nv);
    solution_.bubble = Eigen::Matrix2Xd::Zero(2, mesh_.num_triangles());
  }
  const std::vector<int>& dofs = region_->near_dofs();
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const int d = free_[dofs[k]];
    Eigen::VectorXd& field = d < nv ? solution_.v1 : d < 2 * nv ? solution_.v2 : solution_.p;
    field[d % nv] = x_near[static_cast<Eigen::Index>(k)];
  }
  Eigen::VectorXd z(3 * nv);
  z << solution_.v1, solution_.v2, solution_.p;
  for (int t : region_->near_triangles()) recover_bubble(t, z, chi_[t]);
  solution_.exact_on = &region_->near_mask();
  pending_expansion_ = true;
  timing_.solve += total - assembly - factorization + clock.elapsed();
  return true;
}

// The support of chi and the triangles around it (sharing a vertex with it) inside
// the near region: the structure's vertices, where the coupling samples the fields,
// lie in those triangles, so a near-only solution serves it.
bool PenalisedStokes::near_region_covers(const Eigen::VectorXd& chi) const {
  const std::vector<char>& interior = region_interior_vertex_;
  for (int t = 0; t < mesh_.num_triangles(); ++t)
    if (chi[t] != 0)
      for (int v : mesh_.triangles[t])
        if (!interior[v]) return false;
  return true;
}

// The near region: the triangles meeting the bounding box of χ's support grown by a
// margin, half the box's smaller side (at least 2 triangle sizes) at first and
// doubled whenever χ leaves the region, so that a structure moving across D costs
// a few far-field factorisations, not one per iteration.
void PenalisedStokes::build_near_region() {
  settle_pending_expansion();  // the last solution needs the old region
  region_.reset();
  const Stopwatch clock;
  Point lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  double h_max = 0;
  auto cover = [&](const Eigen::VectorXd& support) {  // grow [lo, hi] over its triangles
    for (int t = 0; t < mesh_.num_triangles(); ++t) {
      if (support[t] == 0) continue;
      const auto& tri = mesh_.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const Point& a = mesh_.vertices[tri[k]];
        lo = lo.cwiseMin(a), hi = hi.cwiseMax(a);
        h_max = std::max(h_max, (a - mesh_.vertices[tri[(k + 1) % 3]]).norm());
      }
    }
  };
  cover(chi_);
  const Point size = hi - lo;
  if (region_margin_ == 0 && region_hint_.size() == chi_.size()) cover(region_hint_);  // the first region only
  region_margin_ = region_margin_ == 0 ? std::max(0.5 * size.minCoeff(), 2 * h_max) : 2 * region_margin_;
  lo.array() -= region_margin_, hi.array() += region_margin_;
  const int nt = mesh_.num_triangles();
  std::vector<char> near(nt, 0);
  int count = 0;
  for (int t = 0; t < nt; ++t) {
    Point a(INFINITY, INFINITY), b(-INFINITY, -INFINITY);
    for (int v : mesh_.triangles[t]) a = a.cwiseMin(mesh_.vertices[v]), b = b.cwiseMax(mesh_.vertices[v]);
    if ((a.array() <= hi.array()).all() && (b.array() >= lo.array()).all()) near[t] = 1, ++count;
  }
  if (2 * count > nt) {  // no gain over the whole factorisation
    region_too_large_ = true;
    return;
  }
  region_interior_vertex_.assign(mesh_.num_vertices(), 1);  // all its triangles near
  for (int t = 0; t < nt; ++t)
    if (!near[t])
      for (int v : mesh_.triangles[t]) region_interior_vertex_[v] = 0;
  region_ = std::make_unique<RegionSchurSolver>(
      unknowns(), near, [this](int t) { return element_dofs(t); },
      [this](int t) { return element_system(t); }, traction_load_, dof_rank(), solver_->name(),
      far_factor_budget_mb_);
  const double elapsed = clock.elapsed();
  timing_.factorization += elapsed;
  timing_.far_factorization += elapsed;
  ++timing_.regions;
  ++timing_.analyses;
}

// Before the last solution's region or ε changes: its deferred expansion, if the
// far factors are at hand (one solve); otherwise (released: it would cost a far-field
// factorisation, for a solution only a failure right after would need) it stays
// exact on its near region only.
void PenalisedStokes::settle_pending_expansion() {
  if (!pending_expansion_) return;
  if (region_->keeps_far_factors()) {
    complete();
  } else {
    stale_mask_ = region_->near_mask();
    solution_.exact_on = &stale_mask_;
    pending_expansion_ = false;
  }
}

// A fill-reducing order of the unknowns, computed once per mesh: METIS nested
// dissection of the vertex graph, each vertex's v1, v2, p kept together. On the
// vertex graph (a third of the nodes, a ninth of the edges of the dof graph) METIS
// is several times faster than on K, for a fill within a few per cent; it serves
// every far-field factorisation of the run.
const std::vector<int>& PenalisedStokes::dof_rank() {
  if (!dof_rank_.empty()) return dof_rank_;
  const int nv = mesh_.num_vertices();
  const std::vector<std::vector<int>> adjacent = vertex_adjacency(mesh_);
  Eigen::SparseMatrix<double> graph(nv, nv);
  std::size_t nnz = 0;
  for (const auto& list : adjacent) nnz += list.size();
  graph.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  graph.outerIndexPtr()[0] = 0;
  for (int v = 0, k = 0; v < nv; ++v) {
    for (int w : adjacent[v]) graph.innerIndexPtr()[k] = w, graph.valuePtr()[k++] = 1.0;
    graph.outerIndexPtr()[v + 1] = graph.outerIndexPtr()[v] + static_cast<int>(adjacent[v].size());
  }
  const std::vector<int> perm = metis_ordering(graph);
  dof_rank_.assign(free_.size(), 0);
  for (int position = 0; position < nv; ++position)
    for (int c = 0; c < 3; ++c) {
      const int r = free_index_[c * nv + perm[position]];
      if (r >= 0) dof_rank_[r] = 3 * position + c;
    }
  return dof_rank_;
}

std::array<int, 9> PenalisedStokes::element_dofs(int t) const {
  std::array<int, 9> dof;
  for (int k = 0; k < 9; ++k) dof[k] = free_index_[fluid_dof(mesh_.triangles[t], k, mesh_.num_vertices())];
  return dof;
}

// The condensed element of triangle t for the current χ and ε, prescribed columns
// lifted to the load.
ElementSystem PenalisedStokes::element_system(int t) const {
  const int nv = mesh_.num_vertices();
  const auto& tri = mesh_.triangles[t];
  const CondensedElement ce = condensed_mini_element(geometry_[t], mu_, chi_[t] / eps_, loads_[t]);
  ElementSystem e{element_dofs(t), ce.K, ce.F};
  for (int j = 0; j < 9; ++j)
    if (e.dof[j] < 0)
      for (int i = 0; i < 9; ++i) e.F[i] -= ce.K(i, j) * z_fixed_[fluid_dof(tri, j, nv)];
  return e;
}

void PenalisedStokes::recover_bubbles(const Eigen::VectorXd& z, const Eigen::VectorXd& chi) {
  solution_.bubble.resize(2, mesh_.num_triangles());
  for (int t = 0; t < mesh_.num_triangles(); ++t) recover_bubble(t, z, chi[t]);
}

// The bubble coefficients of triangle t from the vertex values z (all 3nv dofs) and
// the χ the solution was computed with.
void PenalisedStokes::recover_bubble(int t, const Eigen::VectorXd& z, double chi) {
  const int nv = mesh_.num_vertices();
  const BubbleBlock bb = bubble_block(geometry_[t], mu_, chi / eps_);
  Vector9d local;
  for (int k = 0; k < 9; ++k) local[k] = z[fluid_dof(mesh_.triangles[t], k, nv)];
  solution_.bubble.col(t) = bb.A_bb_inv * (loads_[t].F_b - bb.E * local);
}

}  // namespace fsi
