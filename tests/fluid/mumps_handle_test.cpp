// MUMPS's errors in words (src/fluid/mumps_handle.cpp), and the refusal of
// non-finite data before any factorisation: a NaN handed to MUMPS, UMFPACK or
// CHOLMOD gives undefined behaviour, not an error.
#include "fluid/mumps_handle.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

#include "common/errors.hpp"
#include "fluid/mumps_schur.hpp"

namespace fsi::mumps_handle_test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The INFO(1) codes of the MUMPS 5 users' guide a run of ours can meet, by family;
// every message keeps both codes in brackets.
TEST(MumpsErrorWords, NameTheCauseAndKeepTheCodes) {
  for (int code : {-5, -7, -13, -19})
    EXPECT_TRUE(contains(mumps_error_words(code, 100), "memory")) << code;
  for (int code : {-6, -10}) EXPECT_TRUE(contains(mumps_error_words(code, 7), "singular")) << code;
  for (int code : {-8, -9, -14, -15, -17, -20})
    EXPECT_TRUE(contains(mumps_error_words(code, 5), "workspace")) << code;
  for (int code : {-2,  -3,  -4,  -5,  -6,  -7,  -8,  -9,  -10, -11, -12,
                   -13, -14, -15, -16, -17, -19, -20, -22, -50, -99})
    EXPECT_TRUE(contains(mumps_error_words(code, 42),
                         "[INFO(1) = " + std::to_string(code) + ", INFO(2) = 42]"))
        << mumps_error_words(code, 42);
  // A negative INFO(2) counts millions (the guide, errors -9 and -13).
  EXPECT_TRUE(contains(mumps_error_words(-13, -250), "2.5e+08 entries"))
      << mumps_error_words(-13, -250);
  EXPECT_TRUE(contains(mumps_error_words(-10, 12), "12 pivots")) << mumps_error_words(-10, 12);
  EXPECT_EQ(mumps_error_words(-99, 1), "[INFO(1) = -99, INFO(2) = 1]");  // not one of ours
}

// A real call that fails: an analysis of a matrix of order −1 (INFO(1) = −16).
TEST(MumpsErrorWords, AreWhatAFailedCallReports) {
  MumpsHandle mumps("test: MUMPS ");
  mumps.id().n = -1;
  mumps.id().nnz = 0;
  try {
    mumps.call(1, "analysis");
    FAIL() << "MUMPS analysed a matrix of order -1";
  } catch (const SolverFailure& e) {
    EXPECT_TRUE(
        contains(e.what(), "test: MUMPS analysis failed: the matrix order -1 is out of range"))
        << e.what();
    EXPECT_TRUE(contains(e.what(), "[INFO(1) = -16, INFO(2) = -1]")) << e.what();
  }
}

Eigen::SparseMatrix<double> tridiagonal(int n) {
  Eigen::SparseMatrix<double> A(n, n);
  for (int i = 0; i < n; ++i) {
    A.insert(i, i) = 4.0;
    if (i > 0) A.insert(i, i - 1) = A.insert(i - 1, i) = -1.0;
  }
  A.makeCompressed();
  return A;
}

void expect_refused_as_non_finite(const std::function<void()>& call, const std::string& what) {
  try {
    call();
    ADD_FAILURE() << what << " accepted";
  } catch (const SolverFailure& e) {
    EXPECT_TRUE(contains(e.what(), "non-finite")) << what << ": " << e.what();
  }
}

TEST(MumpsSchur, RefusesNonFiniteData) {
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Eigen::SparseMatrix<double> A = tridiagonal(8);
    A.coeffRef(3, 3) = bad;
    MumpsSchur schur;
    expect_refused_as_non_finite(
        [&] {
          schur.factorize(A, {6, 7});
        },
        "a matrix with " + std::to_string(bad));
    schur.factorize(tridiagonal(8), {6, 7});
    Eigen::VectorXd b = Eigen::VectorXd::Ones(8);
    b[2] = bad;
    expect_refused_as_non_finite([&] { schur.condense(b); },
                                 "a right-hand side with " + std::to_string(bad));
    schur.condense(Eigen::VectorXd::Ones(8));
    expect_refused_as_non_finite([&] { schur.expand(Eigen::Vector2d(1.0, bad)); },
                                 "an x_Γ with " + std::to_string(bad));
  }
}

}  // namespace
}  // namespace fsi::mumps_handle_test
