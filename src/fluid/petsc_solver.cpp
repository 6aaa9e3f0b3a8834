#include "fluid/petsc_solver.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>

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
  int rank = 0, ranks = 1;
  if (const std::string error = plugin->initialise(rank, ranks); !error.empty())
    throw SolverFailure("cannot initialise PETSc: " + error);
  return plugin;  // never unloaded: PETSc and MPI are finalised at exit
}

const PetscPlugin& petsc_plugin() {
  static std::once_flag once;
  static const PetscPlugin* plugin = nullptr;
  std::call_once(once, [] { plugin = load(); });  // a throw leaves the flag unset: the next call retries
  return *plugin;
}

}  // namespace

int launched_ranks() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(variable)) return std::max(1, std::atoi(v));
  return 1;
}

PetscSolver::PetscSolver(const std::string& name, const LinearSolverOptions& options)
    : name_(name), options_(options), iterative_(name == "petsc-iterative"), plugin_(&petsc_plugin()) {}

PetscSolver::~PetscSolver() {
  if (solver_) plugin_->destroy(solver_);
}

// The direct solve's residual is checked as MUMPS's is; an iterative one is only as
// accurate as asked (its own test stopped it there).
double PetscSolver::residual_tolerance() const {
  return iterative_ ? std::max(1e-8, 10 * options_.tol) : SparseDirectSolver::residual_tolerance();
}

void PetscSolver::analyze_pattern(const Eigen::SparseMatrix<double>& A) {
  if (solver_) plugin_->destroy(solver_), solver_ = nullptr;
  PetscSolverConfig config{iterative_, symmetric_, options_.tol, options_.max_iterations, is_pressure_};
  if (iterative_ && static_cast<Eigen::Index>(is_pressure_.size()) != A.rows())
    throw std::logic_error(name_ + ": describe_system() before analyze(), one entry per unknown");
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
  const Eigen::SparseMatrix<double> scaled = diagonal.cwiseInverse().asDiagonal() * Kup;
  S -= Kpu * scaled;
  if (mass.rows() == np) S -= mass;
  return S;
}

}  // namespace

void PetscSolver::factorize_values(const Eigen::SparseMatrix<double>& A) {
  if (wants_pressure_mass()) {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> S = schur_preconditioner(A, is_pressure_, pressure_mass_);
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
  PetscSolveReport report;
  const std::string error = plugin_->solve(solver_, rhs.data(), x.data(), warm, report);
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
  return x;
}

}  // namespace fsi
