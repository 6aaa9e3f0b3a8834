// SPEC §10: fluid.Vmax, fluid.f and structure.f as numbers or expressions in x, y, t.
// The expression is compiled here, once, so that a bad one is an input error (exit 2)
// naming the file, the key and the column; the run compiles it again for its fields
// (run/case_fields.hpp). What the checks between keys see of it: io/case.hpp, above
// StructureParams.
#include <cmath>
#include <optional>
#include <string>

#include "common/expression.hpp"
#include "io/case_section.hpp"

namespace fsi::case_detail {
namespace {

const char* const kExpressionAllowed = "a number, or an expression in x, y, t with pi";

// The text as a message shows it: quoted, cut after 60 characters.
std::string quoted_expression(const std::string& text) {
  return "\"" + (text.size() > 60 ? text.substr(0, 60) + "..." : text) + "\"";
}

// The value of largest magnitude, sign kept, at 5 × 5 points of `box` (its corners and
// edges included) at t = 0: the scale the checks and estimates use for a load that
// varies. Non-finite values are skipped (a pole on a sample point is the run's to find,
// where the field is evaluated: SolverFailure); none finite: 0.
double sampled_magnitude(const Expression& e, const std::array<double, 4>& box) {
  constexpr int n = 5;
  double largest = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = box[0] + (box[2] - box[0]) * i / (n - 1), y = box[1] + (box[3] - box[1]) * j / (n - 1);
      const double v = e(x, y, 0.0);
      if (std::isfinite(v) && std::abs(v) > std::abs(largest)) largest = v;
    }
  return largest;
}

// One expression under `key` (`component`: "" or "(the x component) "): compiled,
// its text into `expression`; a constant is checked as a number in `range`.
double read_expression(const Origin& origin, const std::string& key, const std::string& component,
                       const std::string& text, const Range& range, const std::array<double, 4>& box,
                       std::string& expression) {
  const std::string what = component + "= " + quoted_expression(text);
  std::optional<Expression> e;
  try {
    e.emplace(text);
  } catch (const ExpressionError& error) {
    fail(origin, key, what + ": " + error.what(), kExpressionAllowed);
  }
  expression = text;
  if (!e->varies()) {  // "8.0": the number it is, in the number's range
    const double v = (*e)(0.0, 0.0, 0.0);
    if (!std::isfinite(v)) fail(origin, key, what + " is " + shortest(v) + " everywhere", range.text());
    if (!range.contains(v)) fail(origin, key, what + " = " + shortest(v) + " is out of range", range.text());
    return v;
  }
  const double magnitude = sampled_magnitude(*e, box);
  if (!(std::abs(magnitude) <= kMaxMagnitude))
    fail(origin, key, what + " reaches " + approx(magnitude) + " in the box at t = 0",
         "values of magnitude <= " + shortest(kMaxMagnitude));
  return magnitude;
}

}  // namespace

double Section::number_or_expression(const std::string& key, double value, const Range& range,
                                     std::string& expression, const std::array<double, 4>& box) {
  const toml::node* n = find(key);
  if (!n) return value;
  if (const auto* text = n->as_string()) return read_expression(origin_, full(key), "", text->get(), range, box, expression);
  if (!n->is_number())
    fail(origin_, full(key), "must be a number or a string (an expression)",
         "a number (" + range.text() + "), or an expression in x, y, t with pi");
  expression.clear();
  return number(key, value, range);
}

Point Section::vector2_or_expressions(const std::string& key, Point value, std::array<std::string, 2>& expressions,
                                      const std::array<double, 4>& box, const Range& range) {
  const toml::node* n = find(key);
  if (!n) return value;
  const toml::array* a = n->as_array();
  const std::string allowed = "[a, b], each a number (" + range.text() + ") or an expression in x, y, t with pi";
  const auto usable = [](const toml::node& item) { return item.is_number() || item.is_string(); };
  if (!a || a->size() != 2 || !usable((*a)[0]) || !usable((*a)[1]))
    fail(origin_, full(key), "must be an array of two numbers or expressions", allowed);
  if ((*a)[0].is_number() && (*a)[1].is_number()) {  // as before expressions: the same checks and messages
    expressions = {"", ""};
    return vector2(key, value, range);
  }
  Point v;
  for (int c = 0; c < 2; ++c) {
    const toml::node& item = (*a)[static_cast<std::size_t>(c)];
    const std::string component = c == 0 ? "(the x component) " : "(the y component) ";
    expressions[c].clear();
    if (const auto* text = item.as_string()) {
      v[c] = read_expression(origin_, full(key), component, text->get(), range, box, expressions[c]);
      continue;
    }
    v[c] = as_double(item);
    if (!std::isfinite(v[c])) fail(origin_, full(key), component + "must be finite", allowed);
    if (!range.contains(v[c])) fail(origin_, full(key), component + "= " + shortest(v[c]) + " is out of range", allowed);
  }
  return v;
}

}  // namespace fsi::case_detail
