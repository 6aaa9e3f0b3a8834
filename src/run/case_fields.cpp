#include "run/case_fields.hpp"

#include <cmath>
#include <optional>

#include "common/errors.hpp"
#include "common/expression.hpp"
#include "common/format.hpp"

namespace fsi {
namespace {

// The expression of `text` if it varies; none for a number ("") or a constant. A text
// load_case compiled cannot fail here; a case made in code can.
std::optional<Expression> varying_expression(const std::string& text, const std::string& key) {
  if (text.empty()) return std::nullopt;
  try {
    Expression e(text);
    if (e.varies()) return e;
    return std::nullopt;
  } catch (const ExpressionError& error) {
    throw InputError(key + " = \"" + text + "\": " + error.what() + "; allowed: a number, or an expression in " +
                     kExpressionNames);
  }
}

// e at (x, t), finite, or the run fails naming where.
double finite_value(const Expression& e, const Point& x, double t, const std::string& key) {
  const double v = e(x.x(), x.y(), t);
  if (!std::isfinite(v))
    throw SolverFailure(key + " = \"" + e.text() + "\" is " + shortest(v) + " at (x, y) = (" + approx(x.x(), 6) + ", " +
                        approx(x.y(), 6) + "), t = " + shortest(t));
  return v;
}

// A vector load [a, b]: its numbers (a constant expression's value among them), and
// the components that vary.
VectorField vector_load(const Point& value, const std::array<std::string, 2>& texts, const std::string& key, double t) {
  const std::array<std::string, 2> keys = {key + " (the x component)", key + " (the y component)"};
  const std::array<std::optional<Expression>, 2> e = {varying_expression(texts[0], keys[0]),
                                                      varying_expression(texts[1], keys[1])};
  if (!e[0] && !e[1]) return [value](const Point&) { return value; };
  return [value, e, keys, t](const Point& x) {
    Point v = value;
    for (int c = 0; c < 2; ++c)
      if (e[c]) v[c] = finite_value(*e[c], x, t, keys[c]);
    return v;
  };
}

}  // namespace

VectorField fluid_body_force(const FluidParams& f, double t) {
  return vector_load(f.f, f.f_expression, "fluid.f", t);
}

VectorField structure_body_force(const StructureParams& s, double t) {
  return vector_load(s.f, s.f_expression, "structure.f", t);
}

bool body_force_varies(const StructureParams& s) {
  return varying_expression(s.f_expression[0], "structure.f") || varying_expression(s.f_expression[1], "structure.f");
}

ScalarField inflow_peak(const FluidParams& f, double t) {
  std::optional<Expression> peak = varying_expression(f.Vmax_expression, "fluid.Vmax");
  if (!peak) return [Vmax = f.Vmax](const Point&) { return Vmax; };
  return [e = std::move(*peak), t](const Point& x) { return finite_value(e, x, t, "fluid.Vmax"); };
}

}  // namespace fsi
