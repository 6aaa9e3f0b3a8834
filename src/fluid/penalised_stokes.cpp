#include "fluid/penalised_stokes.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/quadrature.hpp"
#include "common/errors.hpp"
#include "common/timer.hpp"

namespace fsi {
namespace {

ElementLoad element_load(const P1Triangle& T, const VectorField& f, const TriangleRule& rule) {
  ElementLoad load;
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Eigen::Vector3d& l = rule.lambda[q];
    const Point fq = f(T.point(l)) * (rule.w[q] * T.area);
    for (int c = 0; c < 2; ++c) {
      for (int a = 0; a < 3; ++a) load.F_V[3 * c + a] += fq[c] * l[a];
      load.F_b[c] += fq[c] * bubble_value(l);
    }
  }
  return load;
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
  for (int label : bc.dirichlet_labels)
    for (int v : mesh.vertices_on(label)) {
      const Point g = bc.g(mesh.vertices[v]);
      for (int c = 0; c < 2; ++c) {
        fixed[c * nv + v] = true;
        z_fixed_[c * nv + v] = g[c];
      }
    }
  free_index_.assign(3 * nv, -1);
  for (int d = 0; d < 3 * nv; ++d)
    if (!fixed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }

  // Sparsity pattern of the free–free block, built column by column from vertex
  // adjacency (two dofs couple iff their vertices share a triangle): no triplet list,
  // which at hF = 0.0025 would hold 12 million entries.
  const int n = static_cast<int>(free_.size());
  std::vector<std::vector<int>> adjacent(nv);
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      for (int b : tri) adjacent[a].push_back(b);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
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
        const int r = free_index_[fluid_dof(mesh.triangles[t], i, nv)];
        const int c = free_index_[fluid_dof(mesh.triangles[t], j, nv)];
        if (r < 0 || c < 0) continue;
        const int* pos = std::lower_bound(inner + outer[c], inner + outer[c + 1], r);
        slot_[81 * static_cast<std::size_t>(t) + 9 * i + j] = static_cast<int>(pos - inner);
      }

  // Natural boundary: ∫_{edge} h·w ds (bubbles vanish on edges).
  traction_load_ = Eigen::VectorXd::Zero(n);
  const LineRule line = gauss_legendre(3);
  for (const auto& [label, h] : bc.tractions)
    for (const auto& e : mesh.edges_on(label)) {
      const Point& a = mesh.vertices[e.v[0]];
      const Point& b = mesh.vertices[e.v[1]];
      for (std::size_t k = 0; k < line.x.size(); ++k) {
        const double s = line.x[k];
        const Point hq = h((1 - s) * a + s * b) * (line.w[k] * (b - a).norm());
        for (int c = 0; c < 2; ++c) {
          const int r0 = free_index_[c * nv + e.v[0]], r1 = free_index_[c * nv + e.v[1]];
          if (r0 >= 0) traction_load_[r0] += hq[c] * (1 - s);
          if (r1 >= 0) traction_load_[r1] += hq[c] * s;
        }
      }
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
    eps_ = eps;
    chi_changed_ = true;
  }
}

void PenalisedStokes::reset() {
  solved_ = solved_once_ = false;
  assembled_ = false;
  chi_changed_ = true;
  chi_.setZero();
  timing_ = FluidTiming{};
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

const FluidSolution& PenalisedStokes::solve() {
  if (solved_ && !chi_changed_) {
    ++timing_.reused;
    return solution_;
  }
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
      timing_.analysis = clock.elapsed();
      ++timing_.analyses;
    }
    solver_->factorize(K_);
    timing_.factorization += clock.elapsed();
    ++timing_.factorizations;
  }
  const Stopwatch clock;
  const Eigen::VectorXd x = solver_->solve(rhs_);
  if (!x.allFinite()) throw SolverFailure("the Stokes solve produced a non-finite value");
  // A nearly singular matrix can factorise without a zero pivot and give garbage:
  // one product with K (~1% of a factorisation) catches it. The solvers reach
  // ~1e-14 here, up to ε = 1e-7 (docs/performance.md); 1e-8 leaves a wide margin.
  const double residual = (K_ * x - rhs_).norm(), scale = rhs_.norm();
  if (!(residual <= 1e-8 * scale))
    throw SolverFailure("the Stokes matrix is singular or too ill-conditioned for " + solver_->name() +
                        ": relative residual " + std::to_string(residual / scale) + " after the direct solve");
  solved_ = false;  // until the new solution is complete
  Eigen::VectorXd z = z_fixed_;
  for (std::size_t k = 0; k < free_.size(); ++k) z[free_[k]] = x[static_cast<Eigen::Index>(k)];
  const int nv = mesh_.num_vertices();
  solution_.v1 = z.segment(0, nv);
  solution_.v2 = z.segment(nv, nv);
  solution_.p = z.segment(2 * nv, nv);
  recover_bubbles(z);
  timing_.solve += clock.elapsed();
  solved_ = solved_once_ = true;
  chi_changed_ = false;
  solved_chi_ = chi_;
  return solution_;
}

void PenalisedStokes::recover_bubbles(const Eigen::VectorXd& z) {
  const int nv = mesh_.num_vertices();
  solution_.bubble.resize(2, mesh_.num_triangles());
  for (int t = 0; t < mesh_.num_triangles(); ++t) {
    const BubbleBlock bb = bubble_block(geometry_[t], mu_, chi_[t] / eps_);
    Vector9d local;
    for (int k = 0; k < 9; ++k) local[k] = z[fluid_dof(mesh_.triangles[t], k, nv)];
    solution_.bubble.col(t) = bb.A_bb_inv * (loads_[t].F_b - bb.E * local);
  }
}

}  // namespace fsi
