// Expressions in x, y, t (common/expression.hpp, SPEC §10): their values, pi, each
// variable, copies that evaluate on their own (muparser binds variables by address),
// and errors that name the problem and its column.
#include "common/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <thread>
#include <vector>

namespace fsi::expression_test {
namespace {

TEST(Expression, EvaluatesTheVariablesAndPi) {
  EXPECT_EQ(Expression("x")(1.5, 2.5, 3.5), 1.5);
  EXPECT_EQ(Expression("y")(1.5, 2.5, 3.5), 2.5);
  EXPECT_EQ(Expression("t")(1.5, 2.5, 3.5), 3.5);
  EXPECT_EQ(Expression("pi")(0, 0, 0), std::numbers::pi);
  EXPECT_EQ(Expression("_pi")(0, 0, 0), std::numbers::pi);  // muparser's own name, to the last digit too
  EXPECT_EQ(Expression("_e")(0, 0, 0), std::numbers::e);
  // A number as text is that number, exactly: "8.0" runs as Vmax = 8.0 does.
  EXPECT_EQ(Expression("8.0")(0.3, 0.1, 0), 8.0);
  EXPECT_EQ(Expression("-10791.0")(0.3, 0.1, 0), -10791.0);
  // Arithmetic and functions: one rounding per operation, as the same C++ gives
  // (muparser calls std::sin; the tolerance allows for its own order of operations).
  const double x = 0.25, y = -0.5, t = 4.0;
  const double expected = 1.5 * std::sin(std::numbers::pi * t / 8) + 2 * x - y * y + std::exp(-x);
  EXPECT_NEAR(Expression("1.5*sin(pi*t/8) + 2*x - y^2 + exp(-x)")(x, y, t), expected, 4e-16 * std::abs(expected));
  // Comparisons and the ternary are not assignments.
  const Expression step("x <= 0.2 ? 1 : (x == 0.3 ? 2 : 3)");
  EXPECT_EQ(step(0.1, 0, 0), 1.0);
  EXPECT_EQ(step(0.3, 0, 0), 2.0);
  EXPECT_EQ(step(0.4, 0, 0), 3.0);
  EXPECT_EQ(Expression("x != 1")(1, 0, 0), 0.0);
}

TEST(Expression, KnowsWhetherItVaries) {
  EXPECT_TRUE(Expression("0.3*sin(pi*t)").varies());
  EXPECT_TRUE(Expression("8 + 0*y").varies());
  EXPECT_FALSE(Expression("8.0").varies());
  EXPECT_FALSE(Expression("2*pi*sqrt(2)").varies());
  EXPECT_EQ(Expression("  x + 1 ").text(), "  x + 1 ");
}

// NaN and ±inf are values, not errors: the caller names where they came from.
TEST(Expression, NonFiniteValuesAreReturned) {
  EXPECT_TRUE(std::isinf(Expression("1/(x-0.1)")(0.1, 0, 0)));
  EXPECT_TRUE(std::isnan(Expression("sqrt(x)")(-1, 0, 0)));
  EXPECT_EQ(Expression("1/(x-0.1)")(0.6, 0, 0), 2.0);
}

// muparser stores the addresses of the variables: a copy that kept the original's
// would read the original's x, y, t (and, once it is gone, freed memory).
TEST(Expression, ACopyEvaluatesWithVariablesOfItsOwn) {
  std::optional<Expression> original(std::in_place, "x + 10*y + 100*t");
  const Expression copy = *original;
  Expression assigned("0");
  assigned = *original;
  EXPECT_EQ((*original)(1, 2, 3), 321.0);
  EXPECT_EQ(copy(4, 5, 6), 654.0);  // not 321: its own variables
  EXPECT_EQ(assigned(7, 8, 9), 987.0);
  EXPECT_EQ((*original)(1, 2, 3), 321.0);
  original.reset();  // the copies outlive it
  EXPECT_EQ(copy(1, 1, 1), 111.0);
  EXPECT_EQ(assigned(2, 2, 2), 222.0);
  Expression moved = std::move(assigned);  // moving keeps the variables where they are
  EXPECT_EQ(moved(3, 0, 0), 3.0);
}

// One copy per thread: every value is its own point's (a shared parser would mix them).
TEST(Expression, CopiesEvaluateOnTwoThreadsAtOnce) {
  const Expression e("x*x + y");
  std::vector<int> wrong(2, 0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&wrong, k, mine = e] {
      for (int i = 0; i < 20000; ++i) {
        const double x = k + i * 1e-4, y = -k;
        if (mine(x, y, 0) != x * x + y) ++wrong[k];
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(wrong[0], 0);
  EXPECT_EQ(wrong[1], 0);
}

struct Bad {
  const char* text;
  const char* problem;
  int column;  // 1-based; 0: none
};

TEST(Expression, ErrorsNameTheProblemAndItsColumn) {
  const std::vector<Bad> bad = {
      {"0.3*sin(pi*q)", "unknown variable \"q\"", 12},
      {"foo(x)", "unknown function \"foo\"", 1},
      {"2*x + X", "unknown variable \"X\"", 7},  // names are case-sensitive
      {"2*)", "unexpected parenthesis \")\"", 3},
      {"sin(x", "missing parenthesis", 6},
      {"3 x", "unexpected variable \"x\"", 3},
      {"1+", "ends too early", 3},
      {"x=3", "\"=\" assigns (\"==\" compares)", 2},
      {"1, 2", "\",\" starts a second value", 2},
      {"sin(x, y)", "too many parameters for function \"sin\"", 9},
      {"", "is empty", 0},
      {"   ", "is empty", 0},
      {"1e400", "bad number \"1e400\"", 1},
      {"x'", "unexpected \"'\"", 2},
      {"2 # 3", "unexpected \"#\"", 3},
  };
  for (const Bad& b : bad) {
    try {
      Expression e(b.text);
      ADD_FAILURE() << "'" << b.text << "' compiled";
    } catch (const ExpressionError& e) {
      EXPECT_EQ(e.problem, b.problem) << b.text;
      EXPECT_EQ(e.column, b.column) << b.text;
      const std::string what = e.what();
      EXPECT_EQ(what, b.column ? std::string(b.problem) + " at column " + std::to_string(b.column) : b.problem);
    }
  }
  EXPECT_THROW(Expression(std::string(1001, '1')), ExpressionError);  // longer than a load is
}

}  // namespace
}  // namespace fsi::expression_test
