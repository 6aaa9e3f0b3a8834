// The case's loads as the solvers' fields (SPEC §10): fluid.Vmax, fluid.f and
// structure.f are each a number or an expression in x, y, t (io/case.hpp). A number,
// or an expression without x, y, t ("8.0"), is a constant lambda: the arithmetic of
// before, bit for bit. An expression is compiled once per field (a copied field compiles
// its own: common/expression.hpp) and every value it gives is checked: NaN or ±inf is a
// SolverFailure naming the key, the expression and the point.
#pragma once

#include <functional>

#include "fem/vector_p1.hpp"  // VectorField
#include "io/case.hpp"

namespace fsi {

// The time at which a steady run evaluates its expressions.
inline constexpr double kSteadyTime = 0.0;

using ScalarField = std::function<double(const Point&)>;

// f_F of fluid.f, and f_S of structure.f, at time t.
VectorField fluid_body_force(const FluidParams& f, double t = kSteadyTime);
VectorField structure_body_force(const StructureParams& s, double t = kSteadyTime);
// Whether structure.f varies in space (its load integral then needs more than the one
// point that integrates a constant exactly on P1).
bool body_force_varies(const StructureParams& s);
// fluid.Vmax at a point of an inflow side, at time t.
ScalarField inflow_peak(const FluidParams& f, double t = kSteadyTime);

}  // namespace fsi
