// The fluid operator's contract (fluid/mini_element.hpp, fluid/penalised_stokes.hpp):
// the element is a sum of integrators, each the closed form of its term on the mini
// space (P1 + bubble); a term that breaks the symmetry (convection, the Navier–Stokes
// issue) is added without touching the Stokes terms, the solver paths that factor
// symmetric systems only refuse it by name, and an LU path solves it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/errors.hpp"
#include "fem/quadrature.hpp"
#include "fluid/convection.hpp"
#include "fluid/mini_element.hpp"
#include "fluid/penalised_stokes.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"

namespace fsi::operator_contract_test {
namespace {

const P1Triangle kT(Point(0.1, -0.2), Point(0.7, 0.05), Point(0.25, 0.6));

using Basis = MiniVelocityBasis;  // the 8 velocity basis functions at a point (fluid/convection.hpp)

// The 8×8 velocity matrix of a local system: [M_VV  E_col_V; E_row_V  A_bb].
Eigen::Matrix<double, 8, 8> velocity_block(const MiniLocal& e) {
  Eigen::Matrix<double, 8, 8> A;
  A.topLeftCorner<6, 6>() = e.M.topLeftCorner<6, 6>();
  A.topRightCorner<6, 2>() = e.E_col.topRows<6>();
  A.bottomLeftCorner<2, 6>() = e.E_row.leftCols<6>();
  A.bottomRightCorner<2, 2>() = e.A_bb;
  return A;
}

// ∫ form(φ_i, φ_j) over kT's velocity basis by a degree-6 rule (exact for every term
// here: the bubble squared is degree 6).
template <class Form>
Eigen::Matrix<double, 8, 8> by_quadrature(const P1Triangle& T, Form&& form) {
  Eigen::Matrix<double, 8, 8> out = Eigen::Matrix<double, 8, 8>::Zero();
  const TriangleRule rule = triangle_rule(6);
  for (std::size_t q = 0; q < rule.w.size(); ++q) {
    const Basis B = mini_velocity_basis(T, rule.lambda[q]);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) out(i, j) += rule.w[q] * T.area * form(B, i, j);
  }
  return out;
}

// A constant-wind Oseen term ∫ (a·∇v)·w on the mini space by a degree-6 rule (exact:
// bubble times ∇bubble is degree 5): not symmetric.
class OseenTerm final : public ElementTerm {
 public:
  explicit OseenTerm(Eigen::Vector2d wind) : a_(std::move(wind)) {}
  void add(int, const P1Triangle& T, MiniLocal& e) const override {
    // Row i: the test function; column j: the trial function.
    const Eigen::Matrix<double, 8, 8> C =
        by_quadrature(T, [this](const Basis& B, int i, int j) { return B.value[i].dot(B.grad[j] * a_); });
    e.M.topLeftCorner<6, 6>() += C.topLeftCorner<6, 6>();
    e.E_col.topRows<6>() += C.topRightCorner<6, 2>();
    e.E_row.leftCols<6>() += C.bottomLeftCorner<2, 6>();
    e.A_bb += C.bottomRightCorner<2, 2>();
    e.symmetric = false;
  }
  bool symmetric() const override { return false; }

 private:
  Eigen::Vector2d a_;
};

TEST(FluidOperator, TheMassIntegratorIsTheMassOfTheMiniSpace) {
  const double kappa = 3.7;
  MiniLocal e;
  add_mass(kT, kappa, e);
  const Eigen::Matrix<double, 8, 8> brute =
      by_quadrature(kT, [kappa](const Basis& B, int i, int j) { return kappa * B.value[i].dot(B.value[j]); });
  EXPECT_LT((velocity_block(e) - brute).cwiseAbs().maxCoeff(), 1e-14 * brute.cwiseAbs().maxCoeff());
  EXPECT_EQ(e.M.bottomRows<3>().norm(), 0.0);  // no pressure rows: a mass of v only
}

TEST(FluidOperator, TheViscousIntegratorIsTwoMuEpsilonEpsilon) {
  const double mu = 0.35;
  MiniLocal e;
  add_viscous(kT, mu, e);
  const Eigen::Matrix<double, 8, 8> brute = by_quadrature(kT, [mu](const Basis& B, int i, int j) {
    const Eigen::Matrix2d ei = 0.5 * (B.grad[i] + B.grad[i].transpose());
    const Eigen::Matrix2d ej = 0.5 * (B.grad[j] + B.grad[j].transpose());
    return 2 * mu * ei.cwiseProduct(ej).sum();
  });
  EXPECT_LT((velocity_block(e) - brute).cwiseAbs().maxCoeff(), 1e-12 * brute.cwiseAbs().maxCoeff());
}

TEST(FluidOperator, TheGradientFormIsMuGradGrad) {
  const double mu = 0.35;
  MiniLocal e;
  add_viscous_gradient(kT, mu, e);
  const Eigen::Matrix<double, 8, 8> brute = by_quadrature(
      kT, [mu](const Basis& B, int i, int j) { return mu * B.grad[i].cwiseProduct(B.grad[j]).sum(); });
  EXPECT_LT((velocity_block(e) - brute).cwiseAbs().maxCoeff(), 1e-12 * brute.cwiseAbs().maxCoeff());
  MiniLocal symmetric;
  add_viscous(kT, mu, symmetric);  // the two forms differ on a single element (no boundary condition)
  EXPECT_GT((symmetric.M - e.M).norm(), 1e-3 * e.M.norm());
}

TEST(FluidOperator, TheStokesTermsAreSymmetricAndAConvectionTermIsNot) {
  MiniLocal e = mini_local(kT, 0.35, 12.0);
  EXPECT_TRUE(e.symmetric);
  EXPECT_LT((e.M - e.M.transpose()).norm(), 1e-15 * e.M.norm());
  EXPECT_EQ((e.E_col - e.E_row.transpose()).norm(), 0.0);
  EXPECT_LT((e.A_bb - e.A_bb.transpose()).norm(), 1e-15 * e.A_bb.norm());
  OseenTerm(Eigen::Vector2d(1.5, -0.4)).add(0, kT, e);
  EXPECT_FALSE(e.symmetric);
  EXPECT_GT((e.M - e.M.transpose()).norm(), 1e-3 * e.M.norm());
}

// The fluid of the paper's box at a coarse mesh, χ = 0, on a given solver path.
struct Channel {
  Case c = load_case("", {"fluid.h=0.05"});
  Mesh mesh = make_fluid_mesh(c);
  PenalisedStokes stokes(const std::string& solver, FluidFactorization factorization) const {
    const Point f_F = c.fluid->f;
    return PenalisedStokes(mesh, c.fluid->mu, c.coupling.eps, [f_F](const Point&) { return f_F; },
                           box_boundary_conditions(mesh, *c.fluid), solver, factorization);
  }
};

TEST(FluidOperator, AnUnsymmetricTermIsRefusedBySymmetricPathsAndSolvedByLu) {
  const Channel ch;
  const auto oseen = std::make_shared<OseenTerm>(Eigen::Vector2d(0.0, -2.0));  // along the inflow
  const Eigen::VectorXd chi = Eigen::VectorXd::Zero(ch.mesh.num_triangles());
  for (const auto& [solver, factorization] :
       {std::pair{"mumps-metis", FluidFactorization::schur}, std::pair{"mumps-metis", FluidFactorization::whole},
        std::pair{"eigen-ldlt", FluidFactorization::whole}}) {
    PenalisedStokes s = ch.stokes(solver, factorization);
    s.set_chi(chi);
    s.add_term(oseen);
    try {
      s.solve();
      FAIL() << solver << " factored an unsymmetric system";
    } catch (const SolverFailure& e) {
      EXPECT_NE(std::string(e.what()).find("unsymmetric"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(solver), std::string::npos) << e.what();
    }
  }
  PenalisedStokes stokes = ch.stokes("umfpack", FluidFactorization::whole);
  stokes.set_chi(chi);
  const Eigen::VectorXd v_stokes = stokes.solve().v2;
  stokes.add_term(oseen);  // the same χ: a new operator, solved again
  EXPECT_FALSE(stokes.symmetric());
  const FluidSolution umfpack = stokes.solve();
  PenalisedStokes lu = ch.stokes("eigen-lu", FluidFactorization::whole);
  lu.set_chi(chi);
  lu.add_term(oseen);
  const FluidSolution& eigen = lu.solve();
  const double scale = umfpack.v2.cwiseAbs().maxCoeff();
  EXPECT_LT((umfpack.v2 - eigen.v2).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_LT((umfpack.p - eigen.p).cwiseAbs().maxCoeff(), 1e-9 * umfpack.p.cwiseAbs().maxCoeff());
  EXPECT_GT((umfpack.v2 - v_stokes).cwiseAbs().maxCoeff(), 1e-3 * scale);  // the term acts
  // K x = rhs with the unsymmetric K as assembled: an LDLᵀ of its lower triangle would
  // not satisfy it.
  const Eigen::SparseMatrix<double>& K = stokes.matrix();
  EXPECT_GT((Eigen::MatrixXd(K) - Eigen::MatrixXd(K).transpose()).norm(), 1e-6 * Eigen::MatrixXd(K).norm());
}

}  // namespace
}  // namespace fsi::operator_contract_test
