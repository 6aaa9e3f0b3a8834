#include "fluid/mumps_schur.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "fluid/mumps_handle.hpp"
#include "fluid/sparse_solver.hpp"

namespace fsi {

namespace {

// Flags the unknowns of Γ, which must be distinct and in [0, n).
std::vector<char> gamma_marks(const std::vector<int>& gamma, int n) {
  std::vector<char> in_gamma(n, 0);
  for (int g : gamma) {
    if (g < 0 || g >= n || in_gamma[g]) throw std::invalid_argument("MumpsSchur: Γ must be distinct unknowns");
    in_gamma[g] = 1;
  }
  return in_gamma;
}

// Returned by rows; for a symmetric matrix only its lower triangle is filled.
void copy_schur_rows(const std::vector<double>& schur, int ns, Eigen::MatrixXd& S) {
  S.resize(ns, ns);
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j <= i; ++j) S(i, j) = S(j, i) = schur[static_cast<std::size_t>(i) * ns + j];
}

}  // namespace

struct MumpsSchur::Mumps {
  MumpsHandle handle{"MUMPS (Schur complement) "};
  std::vector<MUMPS_INT> rows, columns, position, listvar;
  std::vector<double> values, schur, redrhs;

  DMUMPS_STRUC_C& id() { return handle.id(); }
  MUMPS_INT& icntl(int i) { return handle.icntl(i); }
  void call(int job, const char* phase) { handle.call(job, phase); }

  // Fills rows, columns (and values unless MUMPS can read A's own); returns whether it can.
  bool copy_lower_triangle(const Eigen::SparseMatrix<double>& A);
  // Fills position (MUMPS's PERM_IN) from `order` or METIS, Γ last.
  void set_elimination_order(const Eigen::SparseMatrix<double>& A, const std::vector<int>& gamma,
                             const std::vector<int>& order);
  // Hands A, its ordering and Γ to MUMPS, then analyses and factorises.
  void analyse_and_factorise(const Eigen::SparseMatrix<double>& A, bool in_place, const std::vector<int>& gamma);
  // The solution phase does not read A (no iterative refinement, no error analysis):
  // its coordinate copy goes (20–40 MB at hF = 0.0025).
  void drop_coordinates() {
    rows = {}, columns = {}, values = {};
    id().irn = id().jcn = nullptr;
    id().a = nullptr;
  }
};

// The lower triangle in 1-based coordinates. If A holds only its lower triangle,
// MUMPS reads the values in place (no copy: 19 MB at hF = 0.0025).
bool MumpsSchur::Mumps::copy_lower_triangle(const Eigen::SparseMatrix<double>& A) {
  const int n = static_cast<int>(A.rows());
  std::size_t lower = 0;
  for (int col = 0; col < n; ++col)
    for (int k = A.outerIndexPtr()[col]; k < A.outerIndexPtr()[col + 1]; ++k) lower += A.innerIndexPtr()[k] >= col;
  const bool in_place = lower == static_cast<std::size_t>(A.nonZeros());
  rows.clear(), columns.clear(), values.clear();
  rows.reserve(lower), columns.reserve(lower);
  if (!in_place) values.reserve(lower);
  for (int col = 0; col < n; ++col)
    for (int k = A.outerIndexPtr()[col]; k < A.outerIndexPtr()[col + 1]; ++k)
      if (A.innerIndexPtr()[k] >= col) {
        rows.push_back(A.innerIndexPtr()[k] + 1);
        columns.push_back(col + 1);
        if (!in_place) values.push_back(A.valuePtr()[k]);
      }
  return in_place;
}

// METIS on the whole pattern, the Schur unknowns moved last (MUMPS eliminates them
// last in any case: they form the root of the elimination tree).
void MumpsSchur::Mumps::set_elimination_order(const Eigen::SparseMatrix<double>& A, const std::vector<int>& gamma,
                                              const std::vector<int>& order) {
  const int n = static_cast<int>(A.rows());
  const std::vector<char> in_gamma = gamma_marks(gamma, n);
  if (!order.empty() && order.size() != static_cast<std::size_t>(n))
    throw std::invalid_argument("MumpsSchur: the elimination order must list every unknown");
  const std::vector<int> perm = order.empty() ? metis_ordering(A) : order;
  position.assign(n, 0);
  int next = 1;
  for (int v : perm)
    if (!in_gamma[v]) position[v] = next++;
  for (int g : gamma) position[g] = next++;
  if (next != n + 1 || std::count(position.begin(), position.end(), 0) != 0)
    throw std::invalid_argument("MumpsSchur: the elimination order is not a permutation");
}

void MumpsSchur::Mumps::analyse_and_factorise(const Eigen::SparseMatrix<double>& A, bool in_place,
                                              const std::vector<int>& gamma) {
  const int ns = static_cast<int>(gamma.size());
  listvar.resize(ns);
  for (int k = 0; k < ns; ++k) listvar[k] = gamma[k] + 1;
  schur.assign(static_cast<std::size_t>(ns) * ns, 0.0);

  DMUMPS_STRUC_C& id = this->id();
  id.n = static_cast<int>(A.rows());
  id.nnz = static_cast<MUMPS_INT8>(rows.size());
  id.irn = rows.data();
  id.jcn = columns.data();
  id.a = in_place ? const_cast<double*>(A.valuePtr()) : values.data();
  id.perm_in = position.data();
  icntl(7) = 1;   // the ordering given in perm_in
  icntl(19) = 1;  // Schur complement returned on the host, by rows
  id.size_schur = ns;
  id.listvar_schur = listvar.data();
  id.schur = schur.data();
  call(1, "analysis");
  if (handle.factorize_numeric() == -10)
    throw SolverFailure("MUMPS could not factorise the fluid far from the structure: it is singular "
                        "(INFO(1) = -10); check the Dirichlet boundary");
  handle.check("factorisation");
}

MumpsSchur::MumpsSchur() = default;

MumpsSchur::~MumpsSchur() = default;

void MumpsSchur::factorize(const Eigen::SparseMatrix<double>& A, const std::vector<int>& gamma,
                           const std::vector<int>& order) {
  const int n = static_cast<int>(A.rows());
  const int ns = static_cast<int>(gamma.size());
  if (!A.isCompressed() || A.rows() != A.cols() || ns == 0 || ns >= n)
    throw std::invalid_argument("MumpsSchur: a square compressed matrix and 0 < |Γ| < n unknowns");
  require_finite_matrix(A, "MUMPS (Schur complement)");
  if (!m_) m_ = std::make_unique<Mumps>();
  Mumps& m = *m_;
  const bool in_place = m.copy_lower_triangle(A);
  m.set_elimination_order(A, gamma, order);
  m.analyse_and_factorise(A, in_place, gamma);
  entries_ = static_cast<double>(m.id().infog[28]);
  flops_ = m.id().rinfog[2];
  memory_mb_ = m.id().infog[21];
  m.drop_coordinates();
  copy_schur_rows(m.schur, ns, S_);
  m.schur = {};
  condensed_ = expanded_ = false;
}

void MumpsSchur::release() {
  m_.reset();
  condensed_ = expanded_ = false;
}

Eigen::VectorXd MumpsSchur::condense(const Eigen::VectorXd& b) {
  if (!m_) throw std::logic_error("MumpsSchur: condense() without factors (before factorize() or after release())");
  Mumps& m = *m_;
  if (b.size() != m.id().n) throw std::invalid_argument("MumpsSchur: right-hand side of the wrong size");
  require_finite_rhs(b, "MUMPS (Schur complement)");
  b_ = b;
  Eigen::VectorXd work = b;
  m.redrhs.assign(S_.rows(), 0.0);
  m.id().rhs = work.data();
  m.id().nrhs = 1;
  m.id().lrhs = m.id().n;
  m.id().redrhs = m.redrhs.data();
  m.id().lredrhs = static_cast<MUMPS_INT>(S_.rows());
  m.icntl(26) = 1;  // forward elimination only, the reduced right-hand side in REDRHS
  m.call(3, "condensation");
  m.icntl(26) = 0;
  condensed_ = true;
  expanded_ = false;
  return Eigen::Map<const Eigen::VectorXd>(m.redrhs.data(), S_.rows());
}

Eigen::VectorXd MumpsSchur::expand(const Eigen::VectorXd& x_gamma) {
  if (!m_ || !condensed_) throw std::logic_error("MumpsSchur: expand() before condense()");
  if (x_gamma.size() != S_.rows()) throw std::invalid_argument("MumpsSchur: x_Γ of the wrong size");
  require_finite_rhs(x_gamma, "MUMPS (Schur complement)");
  Mumps& m = *m_;
  // MUMPS keeps the forward elimination of a condensation for one expansion only.
  if (expanded_) condense(Eigen::VectorXd(b_));
  Eigen::VectorXd x = b_;
  std::copy(x_gamma.data(), x_gamma.data() + x_gamma.size(), m.redrhs.begin());
  m.id().rhs = x.data();
  m.id().nrhs = 1;
  m.id().lrhs = m.id().n;
  m.id().redrhs = m.redrhs.data();
  m.id().lredrhs = static_cast<MUMPS_INT>(S_.rows());
  m.icntl(26) = 2;  // backward substitution from x_Γ given in REDRHS
  m.call(3, "expansion");
  m.icntl(26) = 0;
  expanded_ = true;
  return x;
}


}  // namespace fsi
