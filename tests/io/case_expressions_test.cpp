// SPEC §10: fluid.Vmax, fluid.f and structure.f as numbers or expressions in x, y, t
// (io/case_expressions.cpp): a number reads as before, a string is compiled when the
// case is read, a bad one is an input error naming the file, the key and the column,
// and the resolved case writes each back as it was given.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "io/case.hpp"

namespace fsi::case_expressions_test {
namespace {

// The InputError of loading `text` as case.toml with `overrides` ("" if none).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    load_case_text(text, "case.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaseExpressions, ANumberStaysANumber) {
  const Case c = load_case_text("[fluid]\nVmax = 8\nf = [0, -981.0]\n[structure]\nf = [0.0, -10791.0]\n", "case.toml");
  EXPECT_EQ(c.fluid->Vmax, 8.0);
  EXPECT_EQ(c.fluid->Vmax_expression, "");
  EXPECT_EQ(c.fluid->f, Point(0, -981));
  EXPECT_EQ(c.fluid->f_expression, (std::array<std::string, 2>{"", ""}));
  EXPECT_EQ(c.structure.f_expression, (std::array<std::string, 2>{"", ""}));
  EXPECT_EQ(to_toml(c), to_toml(load_case("")));  // the defaults, written as numbers
}

// A constant expression is its number, exactly; the text is kept to be written back.
TEST(CaseExpressions, AConstantStringIsItsNumber) {
  const Case c = load_case_text("[fluid]\nVmax = \"8.0\"\nf = [\"0\", \"-9.81*100\"]\n", "case.toml");
  EXPECT_EQ(c.fluid->Vmax, 8.0);
  EXPECT_EQ(c.fluid->Vmax_expression, "8.0");
  EXPECT_EQ(c.fluid->f, Point(0, -9.81 * 100));
  EXPECT_EQ(c.fluid->f_expression, (std::array<std::string, 2>{"0", "-9.81*100"}));
}

// A varying expression carries, for the checks, its value of largest magnitude (sign
// kept) at 5 × 5 points of its box at t = 0: the fluid box (0, 0.41) × (−0.5, 0.5), the
// structure's rectangle (0, 0.3) × (0, 0.03).
TEST(CaseExpressions, AVaryingStringCarriesItsMagnitudeOnTheBox) {
  const Case c = load_case_text("[fluid]\nVmax = \"8*x/0.41 + 0.3*sin(pi*t)\"\nf = [0, \"-981*(1 + y)\"]\n"
                                "[structure]\nf = [\"0.5*y\", \"-1e4*x/0.3\"]\n", "case.toml");
  EXPECT_DOUBLE_EQ(c.fluid->Vmax, 8.0);  // at x = L1 (t = 0)
  EXPECT_EQ(c.fluid->Vmax_expression, "8*x/0.41 + 0.3*sin(pi*t)");
  EXPECT_EQ(c.fluid->f.x(), 0.0);
  EXPECT_DOUBLE_EQ(c.fluid->f.y(), -981 * 1.5);  // at y = H1, not −490.5 at y = −H2
  EXPECT_DOUBLE_EQ(c.structure.f.x(), 0.5 * 0.03);
  EXPECT_DOUBLE_EQ(c.structure.f.y(), -1e4);
  // The strain check reads that magnitude: too soft for 1e4 N/m³ over a 0.3 m beam.
  const std::string soft = error_of("[structure]\nE = 1e-3\nf = [0, \"-1e4*x/0.3\"]\n[fluid]\nf = [0, 0]\nVmax = 0\n");
  EXPECT_NE(soft.find("structure.E = 0.001 is too soft for the loads"), std::string::npos) << soft;
}

TEST(CaseExpressions, TheResolvedCaseWritesANumberAsANumberAndAnExpressionAsItsText) {
  const Case c = load_case_text("[fluid]\nVmax = \"8.0\"\nf = [0, \"-981*(1+x)\"]\n[structure]\nf = [\"x\", -5]\n",
                                "case.toml");
  const std::string text = to_toml(c);
  EXPECT_NE(text.find("Vmax = '8.0'"), std::string::npos) << text;  // toml++ writes literal strings
  EXPECT_NE(text.find("'-981*(1+x)'"), std::string::npos) << text;
  EXPECT_NE(text.find("f = [ 'x', -5.0 ]"), std::string::npos) << text;
  const Case again = load_case_text(text, "resolved.toml");
  EXPECT_EQ(to_toml(again), text);
  EXPECT_EQ(again.fluid->f_expression, c.fluid->f_expression);
  EXPECT_EQ(again.structure.f_expression, c.structure.f_expression);
}

TEST(CaseExpressions, ABadExpressionNamesTheFileTheKeyAndTheColumn) {
  EXPECT_EQ(error_of("[fluid]\nVmax = \"0.3*sin(pi*q)\"\n"),
            "case.toml: fluid.Vmax = \"0.3*sin(pi*q)\": unknown variable \"q\" at column 12; allowed: a number, or "
            "an expression in x, y, t with pi");
  EXPECT_EQ(error_of("", {"fluid.f=[0, \"-981*(1+\"]"}),
            "--set fluid.f: fluid.f (the y component) = \"-981*(1+\": ends too early at column 9; allowed: a "
            "number, or an expression in x, y, t with pi");
  const std::string unknown = error_of("[structure]\nf = [\"z\", 0]\n");
  EXPECT_NE(unknown.find("case.toml: structure.f (the x component) = \"z\": unknown variable \"z\" at column 1"),
            std::string::npos)
      << unknown;
  // A bare word after --set is a string: an expression without quotes.
  EXPECT_NE(error_of("", {"fluid.Vmax=2*u"}).find("--set fluid.Vmax: fluid.Vmax = \"2*u\": unknown variable \"u\" at column 3"),
            std::string::npos);
  EXPECT_EQ(load_case("", {"fluid.Vmax=0.3*sin(pi*y)"}).fluid->Vmax_expression, "0.3*sin(pi*y)");
}

TEST(CaseExpressions, ANonStringNonNumberIsRefused) {
  const std::string vmax = error_of("[fluid]\nVmax = true\n");
  EXPECT_NE(vmax.find("case.toml: fluid.Vmax must be a number or a string (an expression); allowed: a number (0 or "
                      "a magnitude in [1e-30, 1e+30]), or an expression in x, y, t with pi"),
            std::string::npos)
      << vmax;
  for (const char* f : {"f = [0, true]", "f = [0, [1]]", "f = \"x\"", "f = [0, \"x\", 1]"}) {
    const std::string m = error_of(std::string("[fluid]\n") + f + "\n");
    EXPECT_NE(m.find("case.toml: fluid.f must be an array of two numbers or expressions"), std::string::npos) << m;
  }
}

// A constant is checked as the number it is; a varying one must stay inside a double's
// comfortable range on the box.
TEST(CaseExpressions, ConstantsAreCheckedAsNumbers) {
  EXPECT_NE(error_of("[fluid]\nVmax = \"1/0\"\n").find("fluid.Vmax = \"1/0\" is inf everywhere"), std::string::npos);
  EXPECT_NE(error_of("[fluid]\nVmax = \"1e31\"\n").find("fluid.Vmax = \"1e31\" = 1e+31 is out of range"), std::string::npos);
  EXPECT_NE(error_of("[fluid]\nVmax = \"1e40*x\"\n").find("fluid.Vmax = \"1e40*x\" reaches 4.1e+39 in the box at t = 0"),
            std::string::npos);
  EXPECT_NE(error_of("[structure]\nf = [0, 1e31]\n").find("structure.f = [0, 1e+31] is out of range"), std::string::npos);
  EXPECT_NE(error_of("[structure]\nf = [\"x\", 1e31]\n").find("structure.f (the y component) = 1e+31 is out of range"),
            std::string::npos);
  // A pole on a sample point is not the reader's to refuse (the run names the point it meets).
  EXPECT_EQ(load_case_text("[fluid]\nf = [0, \"1/x\"]\n", "case.toml").fluid->f_expression[1], "1/x");
}

}  // namespace
}  // namespace fsi::case_expressions_test
