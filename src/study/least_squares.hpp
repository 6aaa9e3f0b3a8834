// The least-squares error estimate of Eça & Hoekstra (J. Comput. Phys. 262, 2014) for a
// refinement study whose values scatter (contact zones whose ends jump from vertex to
// vertex, two error sources of opposite signs): φ_i ≈ φ₀ + α h_i^p fitted to all
// levels instead of extrapolated from the finest three, so that one irregular level
// moves the estimate little.
//
//   p is fitted in [0.5, 2.05] (the formal order of P1 elasticity and the mini element
//   is 2; a fitted p beyond that is noise, below 0.5 no convergence is shown);
//   σ the fit's standard deviation, Δφ = (max φ − min φ)/(n − 1) the data's spread;
//   Fs = 1.25 if 0.95 ≤ p ≤ 2.05 and σ < Δφ (a good fit of a plausible order), else 3;
//   U = Fs |φ₁ − φ₀| + σ + |φ₁ − (φ₀ + α h₁^p)|, the uncertainty of the finest value φ₁;
//   where the best p lies outside [0.5, 2.05] (clamped: the data show no plausible
//   order), U is at least 1.25 Δ_M, Δ_M = max φ − min φ over the levels.
// Simplified from the paper: it fits p = 1, p = 2 and their sum besides and picks by
// σ; here p is clamped instead (measured on §7.2: the p = 1 and p = 2 fits' limits lie
// within the U so computed, docs/validation.md).
#pragma once

#include <cmath>
#include <vector>

namespace fsi {

struct LeastSquaresEstimate {
  double limit = NAN;        // φ₀
  double order = NAN;        // p
  double coefficient = NAN;  // α
  double sigma = NAN;        // standard deviation of the fit
  double safety = NAN;       // Fs
  double uncertainty = NAN;  // U (absolute) of the finest value
  bool order_at_bound = false;  // the best p lay outside [0.5, 2.05] and was clamped
};

// `h` and `values` per level (any order, at least four levels; fewer: all NaN).
LeastSquaresEstimate least_squares_estimate(const std::vector<double>& h, const std::vector<double>& values);

}  // namespace fsi
