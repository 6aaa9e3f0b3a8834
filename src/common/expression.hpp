// An expression in x, y, t given as text in a case (SPEC §10: fluid.Vmax, fluid.f,
// structure.f), compiled once by muparser and then evaluated per point.
//
// muparser binds each variable by its address: the values live with the parser, on the
// heap, so a moved Expression keeps them, and a copy compiles the text again around
// variables of its own (a copy evaluated on another thread shares nothing). One object
// is not thread-safe: it writes its variables before each evaluation.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace fsi {

// The names an expression may use, for messages ("an expression in x, y, t with pi").
inline constexpr const char* kExpressionNames = "x, y, t with pi";

// A text that is not an expression of x, y, t: what is wrong ("unknown variable \"q\"")
// and where, the 1-based column of the text (0: nowhere in particular, an empty text).
// what() is the problem followed by " at column N".
struct ExpressionError : std::runtime_error {
  ExpressionError(const std::string& problem, int column);
  std::string problem;
  int column;
};

class Expression {
 public:
  // Compiles `text`: the variables x, y, t, the constant pi (and muparser's own
  // functions, sin, exp, min, the ternary a ? b : c, ...). One value, no assignment.
  // Throws ExpressionError.
  explicit Expression(const std::string& text);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  ~Expression();

  // Its value at (x, y) and time t: NaN or ±inf as the arithmetic gives them (1/0,
  // sqrt(-1)); the caller decides what they mean.
  double operator()(double x, double y, double t) const;
  const std::string& text() const;
  // Whether it reads x, y or t; false: a constant (its value anywhere).
  bool varies() const;

 private:
  struct Compiled;  // the parser and its variables, at a fixed address
  std::unique_ptr<Compiled> compiled_;
};

}  // namespace fsi
