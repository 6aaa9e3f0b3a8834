// The rigid foundation as the graph of ψ (SPEC §1): points with X2 ≥ ψ(X1) are
// admissible. The paper's obstacle is the upper arc of a disk.
#pragma once

#include <cmath>
#include <memory>

namespace fsi {

class Foundation {
 public:
  virtual ~Foundation() = default;
  virtual double psi(double x) const = 0;
  virtual double dpsi(double x) const = 0;
  // Whether ψ is defined (and ψ' finite) at x.
  virtual bool defined_at(double x) const = 0;
};

// ψ(x) = y0 + sqrt(r² − (x − x0)²), ψ'(x) = −(x − x0)/sqrt(r² − (x − x0)²).
class DiskFoundation final : public Foundation {
 public:
  DiskFoundation(double x0, double y0, double r) : x0_(x0), y0_(y0), r_(r) {}
  double psi(double x) const override { return y0_ + root(x); }
  double dpsi(double x) const override { return -(x - x0_) / root(x); }
  bool defined_at(double x) const override { return std::abs(x - x0_) < r_; }
  double x0() const { return x0_; }
  double y0() const { return y0_; }
  double r() const { return r_; }

 private:
  double root(double x) const { return std::sqrt(r_ * r_ - (x - x0_) * (x - x0_)); }
  double x0_, y0_, r_;
};

// ψ(x) = y: a flat rigid floor (used by exact-solution tests).
class FlatFoundation final : public Foundation {
 public:
  explicit FlatFoundation(double y) : y_(y) {}
  double psi(double) const override { return y_; }
  double dpsi(double) const override { return 0.0; }
  bool defined_at(double) const override { return true; }

 private:
  double y_;
};

}  // namespace fsi
