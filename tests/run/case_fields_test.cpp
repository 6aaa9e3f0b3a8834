// The case's loads as fields (run/case_fields.hpp, SPEC §10): a number is the constant
// of before, an expression its values at the point (t = 0), a non-finite value a
// SolverFailure naming the key, the expression and the point, and a copied field
// evaluates on its own.
#include "run/case_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "common/errors.hpp"

namespace fsi::case_fields_test {
namespace {

// The SolverFailure's message of f(x), or "".
template <class Field>
std::string failure_at(const Field& f, const Point& x) {
  try {
    f(x);
  } catch (const SolverFailure& e) {
    return e.what();
  }
  return "";
}

TEST(CaseFields, NumbersAreConstants) {
  const Case c = load_case("");
  EXPECT_EQ(fluid_body_force(*c.fluid)(Point(0.1, 0.2)), Point(0, -981));
  EXPECT_EQ(structure_body_force(c.structure)(Point(0.1, 0.2)), Point(0, -10791));
  EXPECT_EQ(inflow_peak(*c.fluid)(Point(0.1, 0.5)), 8.0);
  EXPECT_FALSE(body_force_varies(c.structure));
  // A constant expression is the same constant.
  const Case s = load_case("", {"fluid.Vmax=\"8.0\"", "structure.f=[\"0\", \"-10791\"]"});
  EXPECT_EQ(inflow_peak(*s.fluid)(Point(0.3, 0.5)), 8.0);
  EXPECT_EQ(structure_body_force(s.structure)(Point(0.3, 0.01)), Point(0, -10791));
  EXPECT_FALSE(body_force_varies(s.structure));
}

TEST(CaseFields, ExpressionsAreEvaluatedAtThePointAtTimeZero) {
  const Case c = load_case("", {"fluid.Vmax=\"8*(1 + x) + t\"", "fluid.f=[\"y\", \"-981*(1+x)\"]",
                                "structure.f=[0, \"-10791*(1 + 10*y)\"]"});
  EXPECT_EQ(inflow_peak(*c.fluid)(Point(0.25, 0.5)), 8 * 1.25);
  EXPECT_EQ(inflow_peak(*c.fluid, 2.0)(Point(0.25, 0.5)), 8 * 1.25 + 2);
  EXPECT_EQ(fluid_body_force(*c.fluid)(Point(0.5, 0.25)), Point(0.25, -981 * 1.5));
  EXPECT_DOUBLE_EQ(structure_body_force(c.structure)(Point(0.1, 0.01))[1], -10791 * 1.1);
  EXPECT_TRUE(body_force_varies(c.structure));
}

TEST(CaseFields, ANonFiniteValueFailsTheRunNamingTheKeyAndThePoint) {
  const Case c = load_case("", {"fluid.f=[0, \"-981*sqrt(x-0.2)\"]", "fluid.Vmax=\"1/(x-0.1)\"",
                                "structure.f=[\"log(y)\", 0]"});
  const VectorField f_F = fluid_body_force(*c.fluid);
  EXPECT_DOUBLE_EQ(f_F(Point(0.29, 0))[1], -981 * std::sqrt(0.29 - 0.2));
  EXPECT_EQ(failure_at(f_F, Point(0.1, 0.25)),
            "fluid.f (the y component) = \"-981*sqrt(x-0.2)\" is nan at (x, y) = (0.1, 0.25), t = 0");
  EXPECT_EQ(failure_at(inflow_peak(*c.fluid), Point(0.1, 0.5)),
            "fluid.Vmax = \"1/(x-0.1)\" is inf at (x, y) = (0.1, 0.5), t = 0");
  EXPECT_EQ(failure_at(structure_body_force(c.structure), Point(0.1, 0)),
            "structure.f (the x component) = \"log(y)\" is -inf at (x, y) = (0.1, 0), t = 0");
}

// Fields are copied (into boundary conditions, the force transfer): each copy compiles
// its own expression, so two copies on two threads give their own points' values.
TEST(CaseFields, ACopiedFieldEvaluatesOnItsOwn) {
  const Case c = load_case("", {"fluid.f=[\"x\", \"y*y\"]"});
  const VectorField original = fluid_body_force(*c.fluid);
  std::vector<int> wrong(2, 0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&wrong, k, f = original] {
      for (int i = 0; i < 20000; ++i) {
        const Point x(k + 1e-4 * i, -k - 1e-4 * i);
        if (f(x) != Point(x.x(), x.y() * x.y())) ++wrong[k];
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(wrong[0], 0);
  EXPECT_EQ(wrong[1], 0);
}

}  // namespace
}  // namespace fsi::case_fields_test
