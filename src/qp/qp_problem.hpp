// The convex QP of the contact problem (paper eqs. 20–22, Dirichlet dofs eliminated):
//     min ½ xᵀ A x − bᵀ x   subject to   C x ≥ c,
// with A symmetric positive definite. α ≥ 0 are the multipliers of the rows of C.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fsi {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct KktResiduals {
  double stationarity = 0;     // ‖Ax − b − Cᵀα‖∞ / (‖A‖∞‖x‖∞ + ‖b‖∞ + ‖Cᵀα‖∞): backward error
  double feasibility = 0;      // max(0, c − Cx)∞, relative to max(‖c‖∞, ‖C‖∞‖x‖∞)
  double complementarity = 0;  // max |α_i (Cx − c)_i|, relative to ‖α‖∞ times that
  // max_i max(0, −α_i)·max_j |C_ij|, the force of a negative α_i, relative as stationarity
  double dual_feasibility = 0;
  double max() const;
};

struct QpResult {
  Eigen::VectorXd x;
  Eigen::VectorXd alpha;      // contact multipliers (discrete contact pressure)
  std::vector<bool> active;   // rows with C x = c at the solution
  int iterations = 0;
  KktResiduals kkt;
  std::string status;         // solver's own words on how it ended
  int active_count() const;
};

// The size of the terms forming a slack Cx − c: max(‖c‖∞, ‖C‖∞‖x‖∞). With a zero
// gap (c = 0, a body resting on the floor) ‖c‖ alone would make round-off look 100%.
double slack_scale(const SparseMatrix& C, const Eigen::VectorXd& c, const Eigen::VectorXd& x);

// "stationarity 1.2e-15, feasibility 0, ..." for messages.
std::string format_kkt(const KktResiduals& r);

KktResiduals kkt_residuals(const SparseMatrix& A, const Eigen::VectorXd& b, const SparseMatrix& C,
                           const Eigen::VectorXd& c, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& alpha);

// What a solver reports for its own multipliers `raw_alpha`: the residuals of
// (x, max(raw_alpha, 0)) — the clamped α the result carries — except the dual
// feasibility, which is that of raw_alpha. Clamping first would report max(0, −α) = 0
// whatever the solver computed, so a solver producing a negative multiplier would pass.
KktResiduals solver_kkt_residuals(const SparseMatrix& A, const Eigen::VectorXd& b,
                                  const SparseMatrix& C, const Eigen::VectorXd& c,
                                  const Eigen::VectorXd& x, const Eigen::VectorXd& raw_alpha);

// A QP solver failed (did not converge, singular operator); carries the status.
struct QpError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// QpError "<who>: <what> has a non-finite entry" unless every entry of M is finite:
// neither solver's behaviour on NaN or ±inf is defined (IPOPT may crash on it).
void require_finite(const SparseMatrix& M, const std::string& who, const std::string& what);
void require_finite(const Eigen::VectorXd& v, const std::string& who, const std::string& what);

class QpSolver {
 public:
  virtual ~QpSolver() = default;
  // Sets the operator A (n×n) and the constraint matrix C (m×n); done once, reused
  // by every later solve (the structure's A_S and C_S do not change in the coupling).
  virtual void set_operator(const SparseMatrix& A, const SparseMatrix& C) = 0;
  // A new constraint matrix C for the same A (contact.gap = "normal" re-linearises
  // C about each new state): A's factorisation is kept.
  virtual void set_constraints(const SparseMatrix& C) = 0;
  // Solves with load b and bounds c. `warm`, if given, is an earlier result used as
  // a starting point. Throws QpError if no minimiser is found.
  virtual QpResult solve(const Eigen::VectorXd& b, const Eigen::VectorXd& c,
                         const QpResult* warm = nullptr) = 0;
  virtual std::string name() const = 0;

  // One line per solver iteration (for a progress display); may be empty.
  std::function<void(const std::string&)> progress;
  // Acceptance threshold on the largest relative KKT residual.
  double kkt_tolerance = 1e-9;
  // The operator is replaced often (each Newton step of a hyperelastic structure,
  // SPEC §11): the active-set solver then factorises it by Eigen's simplicial LLᵀ
  // (AMD order) instead of CHOLMOD's supernodal one, whose BLAS threads cost more
  // than the factorisation at these sizes (§7.2 beam, 154 dofs: 243 µs for a 2-step
  // pass, most of it thread wake-ups under perf). Set before set_operator.
  bool refactorise_often = false;
};

}  // namespace fsi
