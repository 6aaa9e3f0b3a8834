// The update u_{k+1} from u_k and ũ_k = H(u_k) (one fluid solve, force and contact
// QP), SPEC §5. The fixed-point loop holds a Relaxation and does not know which:
//   constant  u_{k+1} = u_k + ω r_k                        (the paper)
//   aitken    ω_k = −ω_{k−1} ⟨r_{k−1}, r_k − r_{k−1}⟩ / ‖r_k − r_{k−1}‖², clamped to
//             [0.01, 1] so the iterate stays a convex combination (Küttler & Wall 2008)
//   iqn-ils   u_{k+1} = ũ_k + W α, α = argmin ‖V α + r_k‖, V, W the differences of
//             residuals and of H (Degroote et al. 2009); projected back onto the
//             feasible set when it leaves it
// with r_k = ũ_k − u_k. Inner products are those of L²(Ω_S0) (the mass matrix M).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace fsi {

// Maps a displacement to the nearest feasible one (the structure operator's norm:
// A_S, A_S + c M in a time step): the structure step's
// (StructureStep::project), given by the loop with each update.
using Projection = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

class Relaxation {
 public:
  virtual ~Relaxation() = default;
  // u^{k+1} from u^k and H(u^k); an update that may leave the feasible set (IQN-ILS's)
  // is projected back by `project` (empty: not projected).
  virtual Eigen::VectorXd next(const Eigen::VectorXd& u, const Eigen::VectorXd& H_u,
                               const Projection& project = {}) = 0;
  // The relaxation factor of the last step (IQN-ILS: NaN after its first step).
  virtual double omega() const = 0;
  virtual std::string name() const = 0;
  // How many updates left the feasible set and were projected back.
  int projections() const { return projections_; }
  // The end of a time window (as preCICE's acceleration has it): the next call to next()
  // starts a new fixed point, so no difference is formed across the windows' boundary.
  // Constant: nothing; Aitken: ω back to ω0; IQN-ILS: the last residual forgotten, and
  // the (V, W) columns kept for RelaxationOptions::reused_windows windows (0: dropped).
  // The steady problem has one window and never calls it.
  virtual void end_window() {}

  // What it carries from one time window to the next, as named arrays (a time run's
  // checkpoint, SPEC §12; run/time_checkpoint.hpp): the projections' count, and
  // IQN-ILS's kept columns with their windows. Constant and Aitken carry nothing more
  // (Aitken starts each window at ω0). restore() takes what saved() gave.
  using State = std::map<std::string, Eigen::VectorXd>;
  virtual State saved() const { return {{"projections", Eigen::VectorXd::Constant(1, projections_)}}; }
  virtual void restore(const State& s) { projections_ = static_cast<int>(s.at("projections")[0]); }

 protected:
  int projections_ = 0;
};

struct RelaxationOptions {
  double omega0 = 0.1;
  int max_columns = 5;          // IQN-ILS: kept difference pairs (chosen on Table 1, docs/validation.md)
  double filter = 1e-2;         // IQN-ILS: drop a column if its new part < filter·its norm
  double omega_min = 1e-2;      // Aitken: clamp to [omega_min, 1]
  int reused_windows = 0;       // IQN-ILS: past windows whose columns end_window() keeps
};

// scheme: "constant" | "aitken" | "iqn-ils"; M: the inner product's matrix.
std::unique_ptr<Relaxation> make_relaxation(const std::string& scheme, const RelaxationOptions& options,
                                            const Eigen::SparseMatrix<double>& M);

}  // namespace fsi
