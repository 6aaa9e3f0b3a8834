// Richardson extrapolation and Roache's Grid Convergence Index for one quantity on a
// sequence of meshes refined by a constant ratio r (ASME V&V 20; the procedure of
// Celik et al., J. Fluids Eng. 130, 2008, with r constant so that its q(p) = 0).
//
// On the finest three levels φ₁ (finest), φ₂, φ₃ with ε₂₁ = φ₂ − φ₁, ε₃₂ = φ₃ − φ₂ and
// R = ε₂₁/ε₃₂:
//   0 < R < 1  monotone convergence,  p = ln(1/R) / ln r,
//   R < 0      oscillatory (p from |R|, the extrapolation is not trusted),
//   R ≥ 1      divergence (p ≤ 0: no extrapolation, no GCI),
//   ε₂₁ = 0    exact: the two finest agree (p undefined, GCI 0);
//   φ_ext = φ₁ + (φ₁ − φ₂)/(r^p − 1),  GCI = 1.25 |ε₂₁/φ₁| / (r^p − 1) (relative).
// The error bar of φ₁: the GCI where it is defined (monotone; 0 when exact); for an
// oscillating sequence, which has no order to extrapolate with, 3 × half the range of
// the finest three (Roache's safety factor for estimates without a verified order;
// the range is what the oscillation shows of the error); none when diverging.
// With four levels or more the asymptotic range is tested the only way three levels
// cannot (their own p makes Roache's ratio test hold by construction): the orders of
// the finest and the next triple must both be monotone and agree within 0.3.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace fsi {

enum class ConvergenceKind { monotone, oscillatory, divergent, exact, too_few };

struct ConvergenceEstimate {
  ConvergenceKind kind = ConvergenceKind::too_few;
  double observed_order = NAN;   // p of the finest three levels
  double extrapolated = NAN;     // φ_ext (monotone only)
  double gci = NAN;              // relative GCI of the finest level (monotone only)
  double gci_abs = NAN;          // gci · |φ₁|
  double error_bar = NAN;        // absolute, of φ₁ (see above)
  std::vector<double> orders;    // p of each consecutive triple, coarsest first
  std::optional<bool> asymptotic;  // none with fewer than four levels
};

// `values` from the coarsest level to the finest; `ratio` > 1 the size ratio between
// consecutive levels; `safety` Roache's factor (1.25 for three or more levels).
ConvergenceEstimate estimate_convergence(const std::vector<double>& values, double ratio, double safety = 1.25);

std::string to_string(ConvergenceKind kind);

}  // namespace fsi
