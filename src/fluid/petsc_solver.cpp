#include "fluid/petsc_solver.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <numeric>

#include "common/errors.hpp"
#include "common/format.hpp"
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
      "PETSc comes from the Debian package libpetsc-real-dev, and this program was built without it if the file is "
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

// On several ranks each owns a contiguous block of rows (petsc_plugin.cpp); the
// assembler numbers the unknowns field by field (v1, v2, p), so a block would be a
// field, not a part of the domain: the pressure's block solve on one rank alone, and
// every velocity row coupled to another rank's. A nested dissection order instead
// numbers one subdomain after the other, each block a part of the domain (its
// separators last): the caller's (set_locality_order), or METIS's on the matrix's
// graph. Every rank computes the same order from the same mesh or matrix.
void PetscSolver::order_for_ranks(const Eigen::SparseMatrix<double>& A) {
  const Eigen::Index n = A.rows(), most = std::max<Eigen::Index>(1, n / options_.min_unknowns_per_rank);
  if (ranks_ > 1 && n / ranks_ < options_.min_unknowns_per_rank)
    throw SolverFailure(name_ + ": " + std::to_string(n) + " unknowns on " + std::to_string(ranks_) +
                        " ranks are fewer than " + std::to_string(options_.min_unknowns_per_rank) +
                        " a rank, too few to keep a rank busy between its exchanges: run on at most " +
                        std::to_string(most) + (most == 1 ? " rank" : " ranks"));
  order_.resize(n);
  if (ranks_ > 1) {
    std::vector<int> pivots(static_cast<std::size_t>(n));  // pivots[k]: the k-th unknown's old number
    if (static_cast<Eigen::Index>(locality_.size()) == n) {
      std::iota(pivots.begin(), pivots.end(), 0);
      std::sort(pivots.begin(), pivots.end(), [this](int a, int b) {
        return locality_[static_cast<std::size_t>(a)] < locality_[static_cast<std::size_t>(b)];
      });
    } else {
      pivots = metis_ordering(A);
    }
    for (Eigen::Index k = 0; k < n; ++k) order_.indices()[pivots[static_cast<std::size_t>(k)]] = static_cast<int>(k);
  } else {
    order_.setIdentity();
  }
}

void PetscSolver::analyze_pattern(const Eigen::SparseMatrix<double>& A) {
  if (solver_) plugin_->destroy(solver_), solver_ = nullptr;
  if (iterative_ && static_cast<Eigen::Index>(is_pressure_.size()) != A.rows())
    throw std::logic_error(name_ + ": describe_system() before analyze(), one entry per unknown");
  order_for_ranks(A);
  std::vector<char> is_pressure(is_pressure_.size());
  for (std::size_t i = 0; i < is_pressure_.size(); ++i)
    is_pressure[static_cast<std::size_t>(order_.indices()[static_cast<Eigen::Index>(i)])] = is_pressure_[i];
  PetscSolverConfig config{iterative_, symmetric_, options_.tol, options_.max_iterations, std::move(is_pressure)};
  is_pressure_ordered_ = config.is_pressure;
  std::string error;
  solver_ = plugin_->create(config, error);
  if (!solver_) throw SolverFailure(name_ + ": " + error);
  last_.resize(0);
}

namespace {

// S_p = D − B diag(A_u)⁻¹ Bᵀ − M_w for K = [A_u Bᵀ; B D] split by is_pressure (D = −C,
// so S_p, like the Schur complement, is negative definite): PETSc's "selfp", which
// follows the penalty (diag(A_u) holds (1/ε)χM), less the fluid's pressure mass matrix
// M_w (w = (1 − χ)/μ), the Stokes Schur complement's spectral equivalent where χ = 0,
// which selfp underestimates on smooth pressures by ~h² (measured:
// docs/performance.md "PETSc").
Eigen::SparseMatrix<double, Eigen::RowMajor> schur_preconditioner(const Eigen::SparseMatrix<double>& K,
                                                                   const std::vector<char>& is_pressure,
                                                                   const Eigen::SparseMatrix<double>& mass) {
  std::vector<int> local(is_pressure.size());
  int nu = 0, np = 0;
  for (std::size_t i = 0; i < is_pressure.size(); ++i) local[i] = is_pressure[i] ? np++ : nu++;
  std::vector<Eigen::Triplet<double>> pu, up, pp;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(nu);
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it) {
      const auto i = static_cast<std::size_t>(it.row());
      const int r = local[i], c = local[static_cast<std::size_t>(j)];
      if (is_pressure[i] && is_pressure[static_cast<std::size_t>(j)]) pp.emplace_back(r, c, it.value());
      else if (is_pressure[i]) pu.emplace_back(r, c, it.value());
      else if (is_pressure[static_cast<std::size_t>(j)]) up.emplace_back(r, c, it.value());
      else if (r == c) diagonal[r] = it.value();
    }
  Eigen::SparseMatrix<double> Kpu(np, nu), Kup(nu, np), S(np, np);
  Kpu.setFromTriplets(pu.begin(), pu.end());
  Kup.setFromTriplets(up.begin(), up.end());
  S.setFromTriplets(pp.begin(), pp.end());
  // diag(A_u)⁻¹ Bᵀ in place: Eigen's sparse = diagonal × sparse inserted entry by entry,
  // 20 % of a solve's time at 223 256 unknowns (perf).
  for (int j = 0; j < Kup.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Kup, j); it; ++it) it.valueRef() /= diagonal[it.row()];
  S -= Kpu * Kup;
  if (mass.rows() == np) S -= mass;
  return S;
}

}  // namespace

// The pressure mass matrix, its rows and columns numbered as the pressure's unknowns
// are in order_.
Eigen::SparseMatrix<double> PetscSolver::ordered_pressure_mass() const {
  if (ranks_ == 1 || pressure_mass_.rows() == 0) return pressure_mass_;
  std::vector<int> ordered_local(is_pressure_ordered_.size(), -1);
  for (std::size_t k = 0, np = 0; k < ordered_local.size(); ++k)
    if (is_pressure_ordered_[k]) ordered_local[k] = static_cast<int>(np++);
  Eigen::PermutationMatrix<Eigen::Dynamic> q(pressure_mass_.rows());
  for (std::size_t i = 0, np = 0; i < is_pressure_.size(); ++i)
    if (is_pressure_[i]) {
      const auto ordered = static_cast<std::size_t>(order_.indices()[static_cast<Eigen::Index>(i)]);
      q.indices()[static_cast<Eigen::Index>(np++)] = ordered_local[ordered];
    }
  return q * pressure_mass_ * q.transpose();
}

void PetscSolver::factorize_values(const Eigen::SparseMatrix<double>& unordered) {
  const Eigen::SparseMatrix<double> A =
      ranks_ == 1 ? unordered : Eigen::SparseMatrix<double>(order_ * unordered * order_.transpose());
  if (wants_pressure_mass()) {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> S =
        schur_preconditioner(A, is_pressure_ordered_, ordered_pressure_mass());
    const PetscCsr csr{static_cast<int>(S.rows()), S.outerIndexPtr(), S.innerIndexPtr(), S.valuePtr()};
    if (const std::string error = plugin_->set_schur_preconditioner(solver_, csr); !error.empty())
      throw SolverFailure(name_ + ": " + error);
  }
  // PETSc's AIJ stores rows; our matrices are stored by column (the transpose's rows).
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = A;
  const PetscCsr csr{static_cast<int>(rows.rows()), rows.outerIndexPtr(), rows.innerIndexPtr(), rows.valuePtr()};
  if (const std::string error = plugin_->set_operator(solver_, csr); !error.empty())
    throw SolverFailure(name_ + ": " + error);
}

Eigen::VectorXd PetscSolver::solve_factorized(const Eigen::VectorXd& rhs) {
  const bool warm = last_.size() == rhs.size();
  Eigen::VectorXd x = warm ? last_ : Eigen::VectorXd::Zero(rhs.size());
  const Eigen::VectorXd b = order_ * rhs;
  PetscSolveReport report;
  const std::string error = plugin_->solve(solver_, b.data(), x.data(), warm, report);
  if (iterative_) last_iterations_ = report.iterations;
  if (!error.empty()) {
    std::string history;
    const std::size_t n = report.history.size(), shown = std::min<std::size_t>(n, 8);
    for (std::size_t k = n - shown; k < n; ++k) history += (history.empty() ? "" : ", ") + approx(report.history[k], 2);
    throw SolverFailure(name_ + ": " + error + " after " + std::to_string(report.iterations) +
                        " iterations; relative residuals, the last " + std::to_string(shown) + ": " + history +
                        " (fluid.linear_tol = " + shortest(options_.tol) +
                        ", fluid.linear_max_iterations = " + std::to_string(options_.max_iterations) + ")");
  }
  last_ = x;
  return order_.transpose() * x;
}

}  // namespace fsi
