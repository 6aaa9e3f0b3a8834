#include "fluid/stokes_assembler.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "fem/integration.hpp"

namespace fsi {

StokesAssembler::StokesAssembler(const Mesh& mesh, double mu, const VectorField& f,
                                 const FluidBoundaryConditions& bc, bool order_now)
    : mesh_(mesh), mu_(mu) {
  if (order_now) order_in_background();  // it needs the mesh only
  const int nv = mesh.num_vertices();
  set_body_force(f);

  // Prescribed velocities on the Dirichlet labels.
  std::vector<bool> fixed(3 * nv, false);
  z_fixed_ = prescribed_values(mesh, bc, fixed);
  free_index_.assign(3 * nv, -1);
  for (int d = 0; d < 3 * nv; ++d)
    if (!fixed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }

  // The number of nonzeros of the whole K (its pattern is built only when the whole
  // matrix is assembled: the substructured solve never needs it).
  {
    std::vector<std::vector<int>> adjacent = vertex_neighbours(mesh);
    for (int col = 0; col < static_cast<int>(free_.size()); ++col)
      for (int component = 0; component < 3; ++component)
        for (int i : adjacent[free_[col] % nv])
          if (free_index_[component * nv + i] >= 0) ++nonzeros_;
  }
  traction_load_ = traction_load(bc);
}

// The prescribed velocities of bc at every dof (0 elsewhere), marking the fixed ones.
Eigen::VectorXd StokesAssembler::prescribed_values(const Mesh& mesh, const FluidBoundaryConditions& bc,
                                                   std::vector<bool>& fixed) {
  const int nv = mesh.num_vertices();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(3 * nv);
  for (int label : bc.dirichlet_labels) {
    const VectorField* value = &bc.g;
    for (const auto& [l, g] : bc.dirichlet_values)
      if (l == label) value = &g;
    for (int v : mesh.vertices_on(label)) {
      const Point g = (*value)(mesh.vertices[v]);
      for (int c = 0; c < 2; ++c) {
        fixed[c * nv + v] = true;
        z[c * nv + v] = g[c];
      }
    }
  }
  return z;
}

// Natural boundary: ∫_{edge} h·w ds on the reduced dofs (bubbles vanish on edges).
Eigen::VectorXd StokesAssembler::traction_load(const FluidBoundaryConditions& bc) const {
  const int nv = mesh_.num_vertices();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_.size()));
  for (const auto& traction : bc.tractions) {
    const auto& h = traction.second;  // a structured binding: clang 14 cannot capture it
    integrate_on_edges(mesh_, mesh_.edges_on(traction.first), gauss_legendre(3), [&](const BoundaryEdge& e, const EdgePoint& q) {
      const Point hq = h(q.x) * q.ds;
      for (int c = 0; c < 2; ++c) {
        const int r0 = free_index_[c * nv + e.v[0]], r1 = free_index_[c * nv + e.v[1]];
        if (r0 >= 0) load[r0] += hq[c] * q.phi[0];
        if (r1 >= 0) load[r1] += hq[c] * q.phi[1];
      }
    });
  }
  return load;
}

void StokesAssembler::set_boundary_data(const FluidBoundaryConditions& bc) {
  std::vector<bool> fixed(z_fixed_.size(), false);
  Eigen::VectorXd z = prescribed_values(mesh_, bc, fixed);
  for (std::size_t d = 0; d < fixed.size(); ++d)
    if (fixed[d] != (free_index_[d] < 0))
      throw std::invalid_argument("set_boundary_data: the velocity must be prescribed on the same labels as before");
  z_fixed_ = std::move(z);
  traction_load_ = traction_load(bc);
  assembled_ = false;  // the lifted columns and the tractions are in rhs_
}

void StokesAssembler::build_whole_pattern() {
  if (K_.rows() == static_cast<Eigen::Index>(free_.size()) && !slot_.empty()) return;
  const Mesh& mesh = mesh_;
  const int nv = mesh.num_vertices();
  // Sparsity pattern of the free–free block, built column by column from vertex
  // adjacency (two dofs couple iff their vertices share a triangle): no triplet list,
  // which at hF = 0.0025 would hold 12 million entries.
  const int n = static_cast<int>(free_.size());
  const std::vector<std::vector<int>> adjacent = vertex_neighbours(mesh);
  std::vector<int> outer_index(n + 1, 0), inner_index;
  for (int col = 0; col < n; ++col) {
    const int j = free_[col] % nv;
    for (int component = 0; component < 3; ++component)  // rows in increasing full index
      for (int i : adjacent[j]) {
        const int r = free_index_[component * nv + i];
        if (r >= 0 && holds(r)) inner_index.push_back(r);
      }
    outer_index[col + 1] = static_cast<int>(inner_index.size());
    // The slots below are 16-bit offsets within a column.
    if (outer_index[col + 1] - outer_index[col] > std::numeric_limits<std::uint16_t>::max())
      throw std::invalid_argument("fluid mesh: a vertex is shared by more than 21 844 triangles; the "
                                  "assembly's offsets (16 bits) cannot address its column");
  }
  K_ = Eigen::SparseMatrix<double>(n, n);
  K_.resizeNonZeros(static_cast<Eigen::Index>(inner_index.size()));
  std::copy(outer_index.begin(), outer_index.end(), K_.outerIndexPtr());
  std::copy(inner_index.begin(), inner_index.end(), K_.innerIndexPtr());
  std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
  slot_.assign(81 * static_cast<std::size_t>(triangles_here()), 0);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  for (int k = 0; k < triangles_here(); ++k) {
    const int t = visited(k);
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        const int r = free_index_[fluid_dof(mesh_.triangles[t], i, nv)];
        const int c = free_index_[fluid_dof(mesh_.triangles[t], j, nv)];
        if (r < 0 || c < 0 || !holds(r)) continue;
        const int* pos = std::lower_bound(inner + outer[c], inner + outer[c + 1], r);
        slot_[81 * static_cast<std::size_t>(k) + 9 * i + j] =
            static_cast<std::uint16_t>(pos - (inner + outer[c]));
      }
  }
}

void StokesAssembler::share_rows(std::vector<char> here) {
  if (!here.empty() && here.size() != free_.size())
    throw std::invalid_argument("share_rows: " + std::to_string(here.size()) + " flags for " +
                                std::to_string(free_.size()) + " unknowns");
  row_here_ = std::move(here);
  triangles_here_.clear();
  here_index_.clear();
  if (!row_here_.empty()) {
    here_index_.assign(static_cast<std::size_t>(mesh_.num_triangles()), -1);
    for (int t = 0; t < mesh_.num_triangles(); ++t) {
      const std::array<int, 9> dof = element_dofs(t);
      if (std::any_of(dof.begin(), dof.end(), [this](int r) { return r >= 0 && holds(r); })) {
        here_index_[static_cast<std::size_t>(t)] = static_cast<int>(triangles_here_.size());
        triangles_here_.push_back(t);
      }
    }
  }
  K_ = Eigen::SparseMatrix<double>();
  slot_.clear();
  assembled_ = false;
}

// Swapped with empty ones: an assignment would keep the capacity.
void StokesAssembler::release_offsets() {
  std::vector<std::uint16_t>().swap(slot_);
  assembled_ = false;  // an update needs them
}

void StokesAssembler::release_matrix() {
  release_offsets();
  Eigen::SparseMatrix<double>().swap(K_);
}

int StokesAssembler::triangles_here() const {
  return row_here_.empty() ? mesh_.num_triangles() : static_cast<int>(triangles_here_.size());
}

const std::uint16_t* StokesAssembler::slots(int t) const {
  const int k = here_index_.empty() ? t : here_index_[static_cast<std::size_t>(t)];
  return &slot_[81 * static_cast<std::size_t>(k)];
}

void StokesAssembler::set_body_force(const VectorField& f) {
  f_ = f;
  std::vector<ElementLoad>().swap(loads_);
  if (keep_loads_) {
    loads_.reserve(static_cast<std::size_t>(mesh_.num_triangles()));
    for (int t = 0; t < mesh_.num_triangles(); ++t) loads_.push_back(element_load(geometry(t), f_, load_rule_));
  }
  assembled_ = false;  // K is unchanged, but rhs_ holds the old loads
}

void StokesAssembler::keep_element_loads(bool keep) {
  if (keep == keep_loads_) return;
  keep_loads_ = keep;
  if (keep) set_body_force(f_);
  else std::vector<ElementLoad>().swap(loads_);
}

MiniLocal StokesAssembler::local(int t, double kappa) const {
  const P1Triangle T = geometry(t);
  MiniLocal e = mini_local(T, mu_, kappa, form_);
  for (const auto& term : terms_) term->add(t, T, e);
  return e;
}

ElementLoad StokesAssembler::load(int t) const {
  ElementLoad load = keep_loads_ ? loads_[t] : element_load(geometry(t), f_, load_rule_);
  if (terms_.empty()) return load;
  const P1Triangle T = geometry(t);
  for (const auto& term : terms_) term->add_load(t, T, load);
  return load;
}

void StokesAssembler::set_viscous_form(ViscousForm form) {
  form_ = form;
  assembled_ = false;
}

void StokesAssembler::add_term(std::shared_ptr<const ElementTerm> term) {
  symmetric_ = symmetric_ && term->symmetric();
  terms_.push_back(std::move(term));
  assembled_ = false;  // the next assemble() assembles every triangle with it
}

// Adds sign × (the condensed element of triangle t with penalty κ) to K and rhs.
// A symmetric element is symmetric to round-off only (the condensation's products
// group its terms differently above and below the diagonal): each pair of K's entries
// takes the value of its lower one (row ≥ column, what MUMPS's LDLᵀ reads), so that a
// symmetric K is symmetric bit for bit, through updates too, and its columns are its
// rows (PETSc then uses K's arrays as they are; petsc_solver.cpp).
void StokesAssembler::add_element(int t, double kappa, double sign) {
  const int nv = mesh_.num_vertices();
  const auto& tri = mesh_.triangles[t];
  const CondensedElement ce = condense(local(t, kappa), load(t));
  const std::uint16_t* slot = slots(t);
  std::array<int, 9> column;  // K's column of each local dof, −1 where prescribed
  for (int j = 0; j < 9; ++j) column[j] = free_index_[fluid_dof(tri, j, nv)];
  const int* outer = K_.outerIndexPtr();
  double* values = K_.valuePtr();
  for (int i = 0; i < 9; ++i) {
    const int r = column[i];
    if (r < 0 || !holds(r)) continue;
    rhs_[r] += sign * ce.F[i];
    for (int j = 0; j < 9; ++j) {
      if (column[j] >= 0)
        values[outer[column[j]] + slot[9 * i + j]] +=
            sign * (symmetric_ && r < column[j] ? ce.K(j, i) : ce.K(i, j));
      else  // prescribed column: lift to the right-hand side
        rhs_[r] -= sign * ce.K(i, j) * z_fixed_[fluid_dof(tri, j, nv)];
    }
  }
}

void StokesAssembler::assemble_full(const Eigen::VectorXd& chi, double eps) {
  build_whole_pattern();
  std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
  rhs_ = traction_load_;
  for (Eigen::Index r = 0; r < rhs_.size(); ++r)
    if (!holds(static_cast<int>(r))) rhs_[r] = 0;
  for (int k = 0; k < triangles_here(); ++k) {
    const int t = visited(k);
    add_element(t, chi[t] / eps, 1.0);
  }
  updates_since_full_ = 0;
  assembled_chi_ = chi;
  assembled_eps_ = eps;
  assembled_ = true;
}

// Between fixed-point iterations χ changes on a few triangles near the structure's
// outline: only those are re-assembled (old contribution out, new in). A full
// assembly is done the first time or for a new ε, when over a tenth of the triangles
// changed, and every 20 updates, which bounds the round-off of the differences.
void StokesAssembler::assemble(const Eigen::VectorXd& chi, double eps) {
  if (!assembled_ || assembled_eps_ != eps || updates_since_full_ >= 20) return assemble_full(chi, eps);
  std::vector<int> changed;
  for (int t = 0; t < mesh_.num_triangles(); ++t)
    if (chi[t] != assembled_chi_[t]) changed.push_back(t);
  if (static_cast<int>(changed.size()) > mesh_.num_triangles() / 10) return assemble_full(chi, eps);
  for (int t : changed) {
    if (!here_index_.empty() && here_index_[static_cast<std::size_t>(t)] < 0) continue;  // no row of it here
    add_element(t, assembled_chi_[t] / eps, -1.0);
    add_element(t, chi[t] / eps, 1.0);
  }
  ++updates_since_full_;
  assembled_chi_ = chi;
}

std::array<int, 9> StokesAssembler::element_dofs(int t) const {
  std::array<int, 9> dof;
  for (int k = 0; k < 9; ++k) dof[k] = free_index_[fluid_dof(mesh_.triangles[t], k, mesh_.num_vertices())];
  return dof;
}

ElementSystem StokesAssembler::element_system(int t, double kappa) const {
  const int nv = mesh_.num_vertices();
  const auto& tri = mesh_.triangles[t];
  const CondensedElement ce = condense(local(t, kappa), load(t));
  ElementSystem e{element_dofs(t), ce.K, ce.F};
  for (int j = 0; j < 9; ++j)
    if (e.dof[j] < 0)
      for (int i = 0; i < 9; ++i) e.F[i] -= ce.K(i, j) * z_fixed_[fluid_dof(tri, j, nv)];
  return e;
}

void StokesAssembler::fields(const Eigen::VectorXd& x, const Eigen::VectorXd& chi, double eps,
                             FluidSolution& out) const {
  fields(x, chi, eps, out, 0, mesh_.num_triangles());
}

void StokesAssembler::fields(const Eigen::VectorXd& x, const Eigen::VectorXd& chi, double eps, FluidSolution& out,
                             int first, int last) const {
  Eigen::VectorXd z = z_fixed_;
  for (std::size_t k = 0; k < free_.size(); ++k) z[free_[k]] = x[static_cast<Eigen::Index>(k)];
  const int nv = mesh_.num_vertices();
  out.v1 = z.segment(0, nv);
  out.v2 = z.segment(nv, nv);
  out.p = z.segment(2 * nv, nv);
  if (first > 0 || last < mesh_.num_triangles())
    out.bubble.setZero(2, mesh_.num_triangles());
  else
    out.bubble.resize(2, mesh_.num_triangles());
  for (int t = first; t < last; ++t) recover_bubble(t, chi[t] / eps, out);
  out.exact_on = nullptr;
}

void StokesAssembler::prescribed_fields(FluidSolution& out) const {
  const int nv = mesh_.num_vertices();
  out.v1 = z_fixed_.segment(0, nv);
  out.v2 = z_fixed_.segment(nv, nv);
  out.p = z_fixed_.segment(2 * nv, nv);
  out.bubble = Eigen::Matrix2Xd::Zero(2, mesh_.num_triangles());
}

Eigen::VectorXd StokesAssembler::reduced(const FluidSolution& s) const {
  const int nv = mesh_.num_vertices();
  Eigen::VectorXd x(static_cast<Eigen::Index>(free_.size()));
  for (std::size_t k = 0; k < free_.size(); ++k) {
    const int d = free_[k];
    x[static_cast<Eigen::Index>(k)] = (d < nv ? s.v1 : d < 2 * nv ? s.v2 : s.p)[d % nv];
  }
  return x;
}

void StokesAssembler::scatter(const std::vector<int>& reduced, const Eigen::VectorXd& x_part, FluidSolution& out) const {
  const int nv = mesh_.num_vertices();
  for (std::size_t k = 0; k < reduced.size(); ++k) {
    const int d = free_[reduced[k]];
    Eigen::VectorXd& field = d < nv ? out.v1 : d < 2 * nv ? out.v2 : out.p;
    field[d % nv] = x_part[static_cast<Eigen::Index>(k)];
  }
}

// The bubble coefficients from the vertex values (static condensation reversed).
void StokesAssembler::recover_bubble(int t, double kappa, FluidSolution& out) const {
  const BubbleBlock bb = bubble_block(local(t, kappa));
  const auto& tri = mesh_.triangles[t];
  Vector9d local;
  for (int k = 0; k < 3; ++k) local[k] = out.v1[tri[k]], local[3 + k] = out.v2[tri[k]], local[6 + k] = out.p[tri[k]];
  out.bubble.col(t) = bb.A_bb_inv * (load(t).F_b - bb.E * local);
}

std::vector<char> StokesAssembler::pressure_unknowns() const {
  const int nv = mesh_.num_vertices();
  std::vector<char> p(free_.size());
  for (std::size_t k = 0; k < free_.size(); ++k) p[k] = free_[k] >= 2 * nv;
  return p;
}

// On a rank holding some rows (share_rows), this rank's rows alone, from the triangles
// it visits: the rest would be built on every rank, then dropped (0.7 s of each of two
// ranks' set-up at 930 000 triangles).
Eigen::SparseMatrix<double> StokesAssembler::pressure_mass(const Eigen::VectorXd& weight) const {
  const int nv = mesh_.num_vertices();
  std::vector<int> row(nv, -1);  // pressure vertex → its row among the pressure unknowns
  std::vector<char> held(nv, 0);
  int n = 0;
  for (std::size_t k = 0; k < free_.size(); ++k)
    if (free_[k] >= 2 * nv) row[free_[k] - 2 * nv] = n++, held[free_[k] - 2 * nv] = holds(static_cast<int>(k));
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * static_cast<std::size_t>(triangles_here()));
  for (int k = 0; k < triangles_here(); ++k) {
    const int t = visited(k);
    const double area = geometry(t).area;
    for (int a = 0; a < 3; ++a) {
      const int v = mesh_.triangles[t][a], i = row[v];
      if (i < 0 || !held[v]) continue;
      for (int b = 0; b < 3; ++b)
        if (const int j = row[mesh_.triangles[t][b]]; j >= 0)
          entries.emplace_back(i, j, weight[t] * bubble::mass_p1(area, a, b));
    }
  }
  Eigen::SparseMatrix<double> M(n, n);
  M.setFromTriplets(entries.begin(), entries.end());
  return M;
}

}  // namespace fsi
