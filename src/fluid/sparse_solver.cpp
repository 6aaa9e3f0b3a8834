#include "fluid/sparse_solver.hpp"

#include <umfpack.h>

#include <Eigen/CholmodSupport>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <type_traits>

#include "common/errors.hpp"
#include "fluid/mumps_handle.hpp"
#include "fluid/petsc_solver.hpp"

namespace fsi {

using SparseMatrix = Eigen::SparseMatrix<double>;

namespace {

// The stored entries, by column: a matrix not yet compressed has gaps in its value array,
// so the first nonZeros() values would not be its entries.
bool all_finite(const SparseMatrix& A) {
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (!std::isfinite(it.value())) return false;
  return true;
}

}  // namespace

void require_finite_matrix(const SparseMatrix& A, const std::string& who) {
  require_finite_matrix(all_finite(A), who);
}

void require_finite_matrix(bool finite, const std::string& who) {
  if (!finite)
    throw SolverFailure(
        who +
        ": the matrix has a non-finite entry (NaN or inf), refused before its "
        "factorisation (is the penalty 1/eps, the viscosity or a load out of range?)");
}

void require_finite_rhs(const Eigen::VectorXd& b, const std::string& who) {
  require_finite_rhs(b.allFinite(), who);
}

void require_finite_rhs(bool finite, const std::string& who) {
  if (!finite)
    throw SolverFailure(who +
                        ": the right-hand side has a non-finite entry (NaN or inf), refused "
                        "before the solve (is a load or a prescribed velocity out of range?)");
}

// FNV-1a over the index words: a changed pattern (a programming error, not an input)
// goes unseen with probability 2^-64, in one pass like the comparison it replaces.
SparseDirectSolver::Pattern SparseDirectSolver::pattern_of(const SparseMatrix& A) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto mix = [&h](const int* first, const int* last) {
    for (; first != last; ++first) h = (h ^ static_cast<std::uint32_t>(*first)) * 0x100000001b3ull;
  };
  mix(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
  mix(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  return {A.cols(), A.nonZeros(), h};
}

void SparseDirectSolver::analyze(const SparseMatrix& A) {
  if (!A.isCompressed() || A.rows() != A.cols())
    throw std::logic_error(name() + ": the matrix must be square and compressed");
  analysed_ = pattern_of(A);
  factorized_ = false;
  analyze_pattern(A);
  ++analyses_;
}

void SparseDirectSolver::factorize(const SparseMatrix& A) {
  if (analyses_ == 0) throw std::logic_error(name() + ": factorize() before analyze()");
  // The symbolic analysis is only valid for the pattern it was done on.
  if (!A.isCompressed() || !(pattern_of(A) == analysed_))
    throw std::logic_error(name() + ": the pattern differs from the analysed one");
  factorized_ = false;
  require_finite_matrix(on_every_rank(all_finite(A)), name());
  factorize_values(A);
  factorized_ = true;
  ++factorizations_;
}

Eigen::VectorXd SparseDirectSolver::solve(const Eigen::VectorXd& rhs) {
  last_iterations_ = -1;
  if (!factorized_) throw std::logic_error(name() + ": solve() without a factorisation");
  if (rhs.size() != analysed_.n)
    throw std::invalid_argument(name() + ": right-hand side of the wrong size");
  require_finite_rhs(on_every_rank(rhs.allFinite()), name());
  return solve_factorized(rhs);
}

void SparseDirectSolver::finish_factorization() {
  if (factorized_) finish_factorization_values();
}

void SparseDirectSolver::release() {
  if (!factorized_) return;
  factorized_ = false;
  release_factorization();
}

Eigen::VectorXd solve_counting_iterations(SparseDirectSolver& solver, const Eigen::VectorXd& rhs,
                                          std::vector<int>& iterations) {
  const auto record = [&] {
    if (solver.last_iterations() >= 0) iterations.push_back(solver.last_iterations());
  };
  try {
    Eigen::VectorXd x = solver.solve(rhs);
    record();
    return x;
  } catch (...) {
    record();
    throw;
  }
}

namespace {

[[noreturn]] void singular(const std::string& solver, const std::string& detail) {
  throw SolverFailure(solver + " could not factorise the Stokes matrix: it is singular (" + detail +
                      "); check the Dirichlet boundary and the penalty ε");
}

using CholmodLdlt = Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower>;
using EigenLdlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;
using EigenLu = Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>;

// Eigen's own solvers and its CHOLMOD wrapper share one shape.
template <class Factorization>
class EigenSolver final : public SparseDirectSolver {
 public:
  explicit EigenSolver(std::string name) : name_(std::move(name)) {}
  Factorization& factorization() { return factorization_; }
  std::string name() const override { return name_; }
  FactorStatistics statistics() const override;
  bool needs_symmetry() const override { return !std::is_same_v<Factorization, EigenLu>; }

 protected:
  void analyze_pattern(const SparseMatrix& A) override { factorization_.analyzePattern(A); }
  void factorize_values(const SparseMatrix& A) override {
    factorization_.factorize(A);
    if (factorization_.info() != Eigen::Success) singular(name_, "a zero pivot");
  }
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) override {
    Eigen::VectorXd x = factorization_.solve(rhs);
    if (factorization_.info() != Eigen::Success) throw SolverFailure(name_ + ": the solve failed");
    return x;
  }

 private:
  std::string name_;
  mutable Factorization factorization_;
};


template <class Factorization>
FactorStatistics EigenSolver<Factorization>::statistics() const {
  return {};
}
template <>
FactorStatistics EigenSolver<CholmodLdlt>::statistics() const {
  const cholmod_common& common = factorization_.cholmod();
  return {common.lnz, common.fl};
}
template <>
FactorStatistics EigenSolver<EigenLdlt>::statistics() const {
  return {static_cast<double>(factorization_.matrixL().nestedExpression().nonZeros()), -1};
}

// UMFPACK through its C interface (the calls Eigen's UmfPackLU makes), which also
// gives its statistics. A is referenced, not copied: the solve's iterative
// refinement reads it, so it must outlive the factorisation (K_ does).
class UmfpackSolver final : public SparseDirectSolver {
 public:
  explicit UmfpackSolver(std::string name) : name_(std::move(name)) {
    umfpack_di_defaults(control_);
    std::fill(std::begin(info_), std::end(info_), -1.0);
  }
  ~UmfpackSolver() override {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;
  double& control(int i) { return control_[i]; }
  std::string name() const override { return name_; }
  FactorStatistics statistics() const override {
    return {info_[UMFPACK_LNZ] + info_[UMFPACK_UNZ], info_[UMFPACK_FLOPS]};
  }
  bool needs_symmetry() const override { return false; }  // LU: any matrix

 protected:
  void analyze_pattern(const SparseMatrix& A) override {
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
    const int n = static_cast<int>(A.rows());
    check(umfpack_di_symbolic(n, n, A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(), &symbolic_,
                              control_, info_),
          "analysis");
  }
  void factorize_values(const SparseMatrix& A) override {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    matrix_ = &A;
    const int status = umfpack_di_numeric(A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(),
                                          symbolic_, &numeric_, control_, info_);
    if (status == UMFPACK_WARNING_singular_matrix)
      singular(name_, "UMFPACK status 1, a zero pivot");
    check(status, "factorisation");
  }
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) override {
    Eigen::VectorXd x(rhs.size());
    double info[UMFPACK_INFO];
    check(umfpack_di_solve(UMFPACK_A, matrix_->outerIndexPtr(), matrix_->innerIndexPtr(),
                           matrix_->valuePtr(), x.data(), rhs.data(), numeric_, control_, info),
          "solve");
    return x;
  }

 private:
  void check(int status, const char* phase) const {
    if (status != UMFPACK_OK)
      throw SolverFailure(name_ + ": UMFPACK " + phase + " failed, status " +
                          std::to_string(status));
  }
  std::string name_;
  double control_[UMFPACK_CONTROL], info_[UMFPACK_INFO];
  void *symbolic_ = nullptr, *numeric_ = nullptr;
  const SparseMatrix* matrix_ = nullptr;
};

// METIS nested dissection of the pattern of the symmetric A, through CHOLMOD (which
// links METIS on Debian; MUMPS's Debian build does not). perm[k] = the k-th pivot.
}  // namespace

std::vector<int> metis_ordering(const SparseMatrix& A) {
  // METIS (GKlib) keeps its random generator's state in globals, reseeded by each
  // call: two orderings at once draw from one sequence and differ from run to run
  // (found when the fluid's vertex order moved to a second thread: a fluid-alone
  // run's force changed in its 16th digit between two runs of one case).
  static std::mutex metis;
  const std::lock_guard<std::mutex> one_at_a_time(metis);
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(A.rows());
  view.nzmax = static_cast<std::size_t>(A.nonZeros());
  view.p = const_cast<int*>(A.outerIndexPtr());
  view.i = const_cast<int*>(A.innerIndexPtr());
  view.x = const_cast<double*>(A.valuePtr());
  view.stype = -1;  // symmetric: the lower triangle is read
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = view.packed = 1;
  std::vector<int> perm(static_cast<std::size_t>(A.rows()));
  const int ok = cholmod_metis(&view, nullptr, 0, 1, perm.data(), &common);
  cholmod_finish(&common);
  if (!ok) throw SolverFailure("METIS (through CHOLMOD) could not order the Stokes matrix");
  return perm;
}

namespace {

// MUMPS, sequential, symmetric indefinite (SYM = 2): multifrontal LDLᵀ with
// threshold 1×1/2×2 pivoting and scaling computed at each factorisation, on the
// lower triangle of A in coordinate form; or unsymmetric (SYM = 0: LU with threshold
// partial pivoting, every entry given), for Navier–Stokes's Jacobian.
class MumpsSolver final : public SparseDirectSolver {
 public:
  enum class Ordering { metis, pord, amd, given };
  // Ordering::given: `order` lists the unknowns in elimination order.
  MumpsSolver(std::string name, Ordering ordering, std::vector<int> order = {}, bool symmetric = true)
      : name_(std::move(name)),
        ordering_(ordering),
        order_(std::move(order)),
        symmetric_(symmetric),
        mumps_(name_ + ": MUMPS ", symmetric ? 2 : 0) {
    if (symmetric) icntl(12) = 1;  // plain ordering of the pattern: the analysis ignores the values
    icntl(7) = ordering == Ordering::metis || ordering == Ordering::given ? 1 : ordering == Ordering::pord ? 4 : 0;
    mumps_.keep_workspace();
  }
  std::string name() const override { return name_; }
  FactorStatistics statistics() const override {
    return {static_cast<double>(id_.infog[28]), id_.rinfog[2]};  // INFOG(29), RINFOG(3)
  }
  bool needs_symmetry() const override { return symmetric_; }  // SYM = 2 reads the lower triangle

 protected:
  void analyze_pattern(const SparseMatrix& A) override {
    rows_.clear(), columns_.clear(), slots_.clear();
    for (int col = 0; col < A.cols(); ++col)
      for (int k = A.outerIndexPtr()[col]; k < A.outerIndexPtr()[col + 1]; ++k)
        if (!symmetric_ || A.innerIndexPtr()[k] >= col) {
          rows_.push_back(A.innerIndexPtr()[k] + 1);
          columns_.push_back(col + 1);
          slots_.push_back(k);
        }
    gather(A);
    id_.n = static_cast<MUMPS_INT>(A.rows());
    id_.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id_.irn = rows_.data();
    id_.jcn = columns_.data();
    if (ordering_ == Ordering::metis || ordering_ == Ordering::given) {
      if (ordering_ == Ordering::given && order_.size() != static_cast<std::size_t>(A.rows()))
        throw std::invalid_argument(name_ + ": the given order does not list every unknown");
      const std::vector<int> perm = ordering_ == Ordering::given ? order_ : metis_ordering(A);
      position_.assign(perm.size(), 0);
      for (std::size_t k = 0; k < perm.size(); ++k) position_[perm[k]] = static_cast<int>(k) + 1;
      id_.perm_in = position_.data();
    }
    call(1, "analysis");
  }

  void factorize_values(const SparseMatrix& A) override {
    gather(A);
    if (mumps_.factorize_numeric() == -10) singular(name_, "MUMPS INFO(1) = -10");
    mumps_.check("factorisation");
  }

  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& rhs) override {
    Eigen::VectorXd x = rhs;
    id_.rhs = x.data();
    call(3, "solve");
    return x;
  }

 private:
  MUMPS_INT& icntl(int i) { return mumps_.icntl(i); }
  void call(int job, const char* phase) { mumps_.call(job, phase); }
  void gather(const SparseMatrix& A) {
    values_.resize(slots_.size());
    for (std::size_t k = 0; k < slots_.size(); ++k) values_[k] = A.valuePtr()[slots_[k]];
    id_.a = values_.data();
  }
  std::string name_;
  Ordering ordering_;
  std::vector<int> order_;  // Ordering::given: the unknowns in elimination order
  bool symmetric_;
  MumpsHandle mumps_;
  DMUMPS_STRUC_C& id_ = mumps_.id();
  std::vector<MUMPS_INT> rows_, columns_, position_;
  std::vector<int> slots_;  // (lower-triangle) entry k is A.valuePtr()[slots_[k]]
  std::vector<double> values_;
};

std::unique_ptr<SparseDirectSolver> make_umfpack_metis() {
  auto solver = std::make_unique<UmfpackSolver>("umfpack-metis");
  solver->control(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
  solver->control(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
  solver->control(UMFPACK_IRSTEP) =
      0;  // refinement: up to two more solves, for 5e-15 instead of 2e-14
  return solver;
}

std::unique_ptr<SparseDirectSolver> make_cholmod_ldlt() {
  auto solver = std::make_unique<EigenSolver<CholmodLdlt>>("cholmod-ldlt");
  cholmod_common& common = solver->factorization().cholmod();
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_METIS;
  common.postorder = 1;
  return solver;
}

}  // namespace

const std::vector<std::string>& sparse_solver_names() {
  static const std::vector<std::string> names = {"mumps-metis", "mumps-pord",    "mumps-amd",
                                                 "umfpack",     "umfpack-metis", "cholmod-ldlt",
                                                 "eigen-ldlt",  "eigen-lu",      "mumps-lu"};
  return names;
}

std::unique_ptr<SparseDirectSolver> make_mumps_solver(std::vector<int> order) {
  return std::make_unique<MumpsSolver>("mumps-given-order", MumpsSolver::Ordering::given, std::move(order));
}

std::unique_ptr<SparseDirectSolver> make_sparse_solver(const std::string& name, const LinearSolverOptions& options) {
  using Ordering = MumpsSolver::Ordering;
  if (name == "petsc-mumps" || name == "petsc-iterative") return std::make_unique<PetscSolver>(name, options);
  if (name == "mumps-metis") return std::make_unique<MumpsSolver>(name, Ordering::metis);
  if (name == "mumps-pord") return std::make_unique<MumpsSolver>(name, Ordering::pord);
  if (name == "mumps-amd") return std::make_unique<MumpsSolver>(name, Ordering::amd);
  if (name == "mumps-lu") return std::make_unique<MumpsSolver>(name, Ordering::metis, std::vector<int>{}, false);
  if (name == "umfpack") return std::make_unique<UmfpackSolver>(name);
  if (name == "umfpack-metis") return make_umfpack_metis();
  if (name == "cholmod-ldlt") return make_cholmod_ldlt();
  if (name == "eigen-ldlt") return std::make_unique<EigenSolver<EigenLdlt>>(name);
  if (name == "eigen-lu") return std::make_unique<EigenSolver<EigenLu>>(name);
  std::string known;
  for (const auto& n : sparse_solver_names()) known += (known.empty() ? "" : ", ") + n;
  known += ", petsc-mumps, petsc-iterative";
  throw std::invalid_argument("unknown sparse solver '" + name + "'; known: " + known);
}

}  // namespace fsi
