#include "fluid/petsc_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/plugin_loader.hpp"
#include "fluid/petsc_plugin.hpp"

namespace fsi {
namespace {

const PetscPlugin* load() {
  // Deep binding: the program links sequential MUMPS, whose stub MPI library defines
  // MPI_Init, MPI_Comm_rank and MPI_Finalize, and MUMPS's own symbols; PETSc and its
  // parallel MUMPS must bind to OpenMPI's and their own instead.
  const PetscPlugin* plugin = load_plugin_table<PetscPlugin>(
      "libfsicontact_petsc.so", "fsicontact_petsc_plugin", "the PETSc plugin",
      "PETSc comes from the Debian package libpetsc-real-dev, and this program was built without "
      "it if the file is "
      "missing; fluid.linear_solver = \"mumps\" needs no PETSc",
      kPetscPluginVersion, true);
  return plugin;  // never unloaded: PETSc and MPI are finalised at exit
}

struct Started {
  const PetscPlugin* plugin = nullptr;
  int ranks = 1;
};

// The plugin, PETSc and MPI started once per process.
Started petsc_started() {
  static std::once_flag once;
  static Started started;
  std::call_once(once, [] {  // a throw leaves the flag unset: the next call retries
    const PetscPlugin* plugin = load();
    int rank = 0, ranks = 1;
    if (const std::string error = plugin->initialise(rank, ranks); !error.empty())
      throw SolverFailure("cannot initialise PETSc: " + error);
    started = {plugin, ranks};
    if (ranks > 1) {
      // A stop asked of one rank is every rank's (common/interrupt.hpp); no longer
      // once MPI is finalised (atexit: this handler, registered after PETSc's, runs first).
      agree_on_interrupts(plugin->largest_over_ranks);
      std::atexit([] { agree_on_interrupts(nullptr); });
    }
  });
  return started;
}

}  // namespace

PetscSolver::PetscSolver(const std::string& name, const LinearSolverOptions& options)
    : name_(name), options_(options), iterative_(name == "petsc-iterative") {
  const Started started = petsc_started();
  plugin_ = started.plugin;
  ranks_ = started.ranks;
}

PetscSolver::~PetscSolver() {
  if (solver_) plugin_->destroy(solver_);
}

// The direct solve's residual is checked as MUMPS's is; an iterative one is only as
// accurate as asked (its own test stopped it there).
double PetscSolver::residual_tolerance() const {
  return iterative_ ? std::max(1e-8, 10 * options_.tol) : SparseDirectSolver::residual_tolerance();
}

// SolverFailure naming the most ranks n unknowns can feed, if fewer than
// min_unknowns_per_rank fall to each rank.
void PetscSolver::require_enough_unknowns(Eigen::Index n) const {
  const Eigen::Index most = std::max<Eigen::Index>(1, n / options_.min_unknowns_per_rank);
  if (ranks_ > 1 && n / ranks_ < options_.min_unknowns_per_rank)
    throw SolverFailure(
        name_ + ": " + std::to_string(n) + " unknowns on " + std::to_string(ranks_) +
        " ranks are fewer than " + std::to_string(options_.min_unknowns_per_rank) +
        " a rank, too few to keep a rank busy between its exchanges: run on at most " +
        std::to_string(most) + (most == 1 ? " rank" : " ranks"));
}

// On several ranks each owns a contiguous block of rows (petsc_plugin.cpp); the
// assembler numbers the unknowns field by field (v1, v2, p), so a block would be a
// field, not a part of the domain: the pressure's block solve on one rank alone, and
// every velocity row coupled to another rank's. An order that keeps neighbours
// together instead makes each block a part of the domain: the caller's
// (set_locality_order), or METIS's nested dissection of the matrix's graph. Every rank
// computes the same order from the same mesh or matrix.
// pivots[k]: the k-th unknown's old number; this rank's block of rows in that order.
void PetscSolver::set_order(const std::vector<int>& pivots) {
  const auto n = static_cast<Eigen::Index>(pivots.size());
  order_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k)
    order_.indices()[pivots[static_cast<std::size_t>(k)]] = static_cast<int>(k);
  plugin_->row_block(static_cast<int>(n), first_, last_);
  const std::vector<std::pair<int, int>> blocks = row_blocks(static_cast<int>(n));
  if (std::find(blocks.begin(), blocks.end(), std::pair{first_, last_}) == blocks.end())
    throw std::logic_error(name_ + ": the plugin's block of rows is not PETSc's even split");
}

// Every rank's block of rows [first, last) of n, rank by rank: PETSc's even split, the
// plugin's row_block (set_order checks that they agree).
std::vector<std::pair<int, int>> PetscSolver::row_blocks(int n) const {
  std::vector<std::pair<int, int>> blocks;
  const int base = n / ranks_, extra = n % ranks_;
  for (int r = 0, first = 0; r < ranks_; ++r) {
    const int last = first + base + (r < extra ? 1 : 0);
    blocks.emplace_back(first, last);
    first = last;
  }
  return blocks;
}

// The curve's order cut into the ranks' blocks, and each block back in the caller's
// order: the assembler's, field by field (v1, v2, p), each in the mesh's order. Left
// interleaved by vertex along the curve, the velocity block's BoomerAMG hierarchy cost
// more to build and did less: at 930 681 triangles on two ranks GMRES took 113
// iterations against one rank's 107, and 107 in this order, with the set-up's
// hierarchies 1.44 -> 1.09 s and the Krylov solve 13.2 -> 11.9 s (docs/performance.md,
// "Each rank's unknowns in the assembler's order").
void PetscSolver::set_locality_order(std::vector<int> rank) {
  require_enough_unknowns(static_cast<Eigen::Index>(rank.size()));
  std::vector<int> pivots(rank.size());
  std::iota(pivots.begin(), pivots.end(), 0);
  std::sort(pivots.begin(), pivots.end(), [&rank](int a, int b) {
    return rank[static_cast<std::size_t>(a)] < rank[static_cast<std::size_t>(b)];
  });
  for (const auto& [first, last] : row_blocks(static_cast<int>(pivots.size())))
    std::sort(pivots.begin() + first, pivots.begin() + last);
  set_order(pivots);
}

void PetscSolver::order_for_ranks(const Eigen::SparseMatrix<double>& A) {
  require_enough_unknowns(A.rows());
  std::vector<int> pivots(static_cast<std::size_t>(A.rows()));
  if (ranks_ > 1)
    pivots = metis_ordering(A);
  else
    std::iota(pivots.begin(), pivots.end(), 0);
  set_order(pivots);
}

std::vector<char> PetscSolver::rows_here() const {
  if (ranks_ == 1) return {};
  std::vector<char> here(static_cast<std::size_t>(order_.size()));
  for (Eigen::Index i = 0; i < order_.size(); ++i)
    here[static_cast<std::size_t>(i)] =
        order_.indices()[i] >= first_ && order_.indices()[i] < last_;
  return here;
}

double PetscSolver::sum_over_ranks(double value) const {
  if (ranks_ == 1) return value;
  if (const std::string error = plugin_->sum_over_ranks(&value, 1); !error.empty())
    throw SolverFailure(name_ + ": " + error);
  return value;
}

std::pair<int, int> PetscSolver::share(int count) const {
  int first = 0, last = count;
  if (ranks_ > 1) plugin_->row_block(count, first, last);
  return {first, last};
}

void PetscSolver::sum_shares(double* values, Eigen::Index count) const {
  if (ranks_ == 1) return;
  if (count > std::numeric_limits<int>::max())
    throw std::logic_error(name_ + ": too many values to sum over the ranks at once");
  if (const std::string error = plugin_->sum_over_ranks(values, static_cast<int>(count)); !error.empty())
    throw SolverFailure(name_ + ": " + error);
}

double PetscSolver::norm_over_ranks(const Eigen::VectorXd& v) const {
  return std::sqrt(sum_over_ranks(v.squaredNorm()));
}

bool PetscSolver::on_every_rank(bool ok) const {
  return sum_over_ranks(ok ? 0.0 : 1.0) == 0.0;
}

void PetscSolver::analyze_pattern(const Eigen::SparseMatrix<double>& A) {
  if (solver_) plugin_->destroy(solver_), solver_ = nullptr;
  if (iterative_ && static_cast<Eigen::Index>(is_pressure_.size()) != A.rows())
    throw std::logic_error(name_ + ": describe_system() before analyze(), one entry per unknown");
  if (order_.size() != A.rows()) order_for_ranks(A);
  std::vector<char> is_pressure(is_pressure_.size());
  for (std::size_t i = 0; i < is_pressure_.size(); ++i)
    is_pressure[static_cast<std::size_t>(order_.indices()[static_cast<Eigen::Index>(i)])] =
        is_pressure_[i];
  const auto pressures = [&is_pressure](int from, int to) {
    return is_pressure.empty() ? 0
                               : static_cast<int>(std::count(is_pressure.begin() + from,
                                                             is_pressure.begin() + to, 1));
  };
  p_first_ = pressures(0, first_);
  p_last_ = p_first_ + pressures(first_, last_);
  PetscSolverConfig config{iterative_, symmetric_, options_.tol, options_.max_iterations, options_.krylov,
                           std::move(is_pressure)};
  pressure_order_ = pressure_order(config.is_pressure);
  std::string error;
  solver_ = plugin_->create(config, error);
  if (!solver_) throw SolverFailure(name_ + ": " + error);
  last_solution_.resize(0);
}

namespace {

// Whether A (compressed, each column's rows sorted) equals its transpose bit for bit:
// each entry below the diagonal against its mirror, found by bisection in its column.
// One pass over A, no copy: 0.13 s for 29 M nonzeros (1.39 M unknowns), where the
// §7.2 box's set-up and solve at that size take ~35 s.
bool is_own_transpose(const Eigen::SparseMatrix<double>& A) {
  const int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
  const double* value = A.valuePtr();
  for (int j = 0; j < A.outerSize(); ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      if (i <= j) continue;
      const int* at = std::lower_bound(inner + outer[i], inner + outer[i + 1], j);
      if (at == inner + outer[i + 1] || *at != j || value[at - inner] != value[k]) return false;
    }
  return true;
}

// Rows [first, last) of P A Pᵀ (P: old number i → to[i]), compressed by rows, each
// row's columns sorted, straight from A's columns (a pass to count, one to fill). A
// holds, on several ranks, this rank's rows alone: P A Pᵀ and then its rows would be
// two more copies. The columns are read in their new order, so that each row's come
// sorted and no row needs sorting afterwards.
struct OrderedRows {
  std::vector<int> start, column;
  std::vector<double> value;
  PetscCsr csr(int n, int first, int last) const {
    return {n, first, last, start.data(), column.data(), value.data()};
  }
};

// The inverse of the numbering to (old → new) of n unknowns: new → old.
std::vector<int> inverse_order(const int* to, int n) {
  std::vector<int> from(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) from[static_cast<std::size_t>(to[j])] = j;
  return from;
}

OrderedRows ordered_rows(const Eigen::SparseMatrix<double>& A, const int* to, int first, int last) {
  OrderedRows r;
  r.start.assign(static_cast<std::size_t>(last - first) + 1, 0);
  const auto held = [&](int i) { return to[i] >= first && to[i] < last; };
  using Entry = Eigen::SparseMatrix<double>::InnerIterator;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Entry it(A, j); it; ++it)
      if (held(static_cast<int>(it.row()))) ++r.start[static_cast<std::size_t>(to[it.row()] - first) + 1];
  std::partial_sum(r.start.begin(), r.start.end(), r.start.begin());
  r.column.resize(static_cast<std::size_t>(r.start.back()));
  r.value.resize(r.column.size());
  const std::vector<int> from = inverse_order(to, static_cast<int>(A.outerSize()));
  std::vector<int> next(r.start.begin(), r.start.end() - 1);
  for (int jn = 0; jn < A.outerSize(); ++jn) {
    const int j = from[static_cast<std::size_t>(jn)];
    for (Entry it(A, j); it; ++it)
      if (held(static_cast<int>(it.row()))) {
        const auto at = static_cast<std::size_t>(next[static_cast<std::size_t>(to[it.row()] - first)]++);
        r.column[at] = jn, r.value[at] = it.value();
      }
  }
  return r;
}

}  // namespace

// The pressure's unknowns' numbers among themselves in order_'s order (the pressure
// mass matrix's rows and columns in the plugin's numbering), by their old ones;
// is_pressure_ordered flags the unknowns in order_'s order.
std::vector<int> PetscSolver::pressure_order(const std::vector<char>& is_pressure_ordered) const {
  std::vector<int> ordered_local(is_pressure_ordered.size(), -1), to;
  for (std::size_t k = 0, np = 0; k < ordered_local.size(); ++k)
    if (is_pressure_ordered[k]) ordered_local[k] = static_cast<int>(np++);
  for (std::size_t i = 0; i < is_pressure_.size(); ++i)
    if (is_pressure_[i])
      to.push_back(
          ordered_local[static_cast<std::size_t>(order_.indices()[static_cast<Eigen::Index>(i)])]);
  return to;
}

void PetscSolver::factorize_values(const Eigen::SparseMatrix<double>& A) {
  if (wants_pressure_mass() && pressure_mass_.rows() > 0) {
    const OrderedRows M = ordered_rows(pressure_mass_, pressure_order_.data(), p_first_, p_last_);
    const auto np = static_cast<int>(pressure_mass_.rows());
    if (const std::string error = plugin_->set_pressure_mass(solver_, M.csr(np, p_first_, p_last_));
        !error.empty())
      throw SolverFailure(name_ + ": " + error);
    pressure_mass_ = {};  // PETSc holds it; the caller gives the next one
  }
  // On one rank a K that is its own transpose bit for bit (StokesAssembler::add_element)
  // has its columns for rows: PETSc uses its arrays in place. They stay unchanged until
  // the solve (petsc-mumps), as SparseDirectSolver's callers keep A, or until
  // set_operator returns (petsc-iterative, which splits K into its blocks then:
  // detaches_from_operator()).
  if (ranks_ == 1 && symmetric_ && is_own_transpose(A)) {
    const PetscCsr K{static_cast<int>(A.rows()), 0, static_cast<int>(A.rows()), A.outerIndexPtr(),
                     A.innerIndexPtr(), A.valuePtr(), true};
    if (const std::string error = plugin_->set_operator(solver_, K); !error.empty())
      throw SolverFailure(name_ + ": " + error);
  } else if (iterative_) {
    // Split from A's columns, read in PETSc's order: no copy of this rank's rows in it.
    const std::vector<int> from = inverse_order(order_.indices().data(), static_cast<int>(A.cols()));
    const PetscColumns columns{static_cast<int>(A.rows()), first_,           last_,
                               A.outerIndexPtr(),          A.innerIndexPtr(), A.valuePtr(),
                               order_.indices().data(),    from.data()};
    if (const std::string error = plugin_->set_operator_columns(solver_, columns); !error.empty())
      throw SolverFailure(name_ + ": " + error);
  } else {
    // The rows freed once PETSc holds them, before the set-up: petsc-mumps's peak at
    // 1.4 M unknowns 4 466 -> 3 984 MB (docs/performance.md "Several ranks").
    const OrderedRows rows = ordered_rows(A, order_.indices().data(), first_, last_);
    const auto n = static_cast<int>(A.rows());
    if (const std::string error = plugin_->set_operator(solver_, rows.csr(n, first_, last_));
        !error.empty())
      throw SolverFailure(name_ + ": " + error);
  }
  if (const std::string error = plugin_->set_up(solver_); !error.empty())
    throw SolverFailure(name_ + ": " + error);
}

void PetscSolver::finish_factorization_values() {
  if (const std::string error = plugin_->finish_set_up(solver_); !error.empty())
    throw SolverFailure(name_ + ": " + error);
}

void PetscSolver::release_factorization() {
  if (!solver_) return;
  if (const std::string error = plugin_->release(solver_); !error.empty())
    throw SolverFailure(name_ + ": " + error);
}

// The vectors beside the set-up, the memory's peak, are few: the last solution is
// moved into the first iterate (not copied), and on one rank, where the order is the
// identity, rhs is given as it is (docs/performance.md, "The run's later passes").
Eigen::VectorXd PetscSolver::solve_factorized(const Eigen::VectorXd& rhs) {
  const bool warm = last_solution_.size() == rhs.size();
  Eigen::VectorXd x = warm ? std::move(last_solution_) : Eigen::VectorXd::Zero(rhs.size());
  last_solution_ = Eigen::VectorXd();
  const Eigen::VectorXd ordered = ranks_ > 1 ? Eigen::VectorXd(order_ * rhs) : Eigen::VectorXd();
  PetscSolveReport report;
  const std::string error = plugin_->solve(solver_, ranks_ > 1 ? ordered.data() : rhs.data(), x.data(), warm, report);
  if (iterative_) last_iterations_ = report.iterations;
  last_residual_ = iterative_ && error.empty() ? report.residual : std::numeric_limits<double>::quiet_NaN();
  if (!error.empty()) {
    std::string history;
    const std::size_t n = report.history.size(), shown = std::min<std::size_t>(n, 8);
    for (std::size_t k = n - shown; k < n; ++k)
      history += (history.empty() ? "" : ", ") + approx(report.history[k], 2);
    throw SolverFailure(
        name_ + ": " + error + " after " + std::to_string(report.iterations) +
        " iterations; relative residuals, the last " + std::to_string(shown) + ": " + history +
        " (fluid.krylov = \"" + options_.krylov + "\", fluid.linear_tol = " + shortest(options_.tol) +
        ", fluid.linear_max_iterations = " + std::to_string(options_.max_iterations) + ")");
  }
  last_solution_ = x;
  if (ranks_ == 1) return x;
  return order_.transpose() * x;
}

}  // namespace fsi
