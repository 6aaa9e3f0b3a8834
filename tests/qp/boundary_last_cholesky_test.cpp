// The factorisation with the contact boundary's dofs last (qp/boundary_last_cholesky):
// solves and the Schur complement S = C A⁻¹ Cᵀ from its trailing block against a plain
// Cholesky's solves, on a P2 beam's stiffness with its contact rows; the fill no worse
// than twice Eigen's default AMD ordering of the whole matrix.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>

#include "qp/boundary_last_cholesky.hpp"
#include "solid/contact.hpp"
#include "solid/p2_elasticity.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::boundary_last_cholesky_test {
namespace {

struct Problem {
  SparseMatrix A, C;
};

Problem beam() {
  const Mesh mesh = testing::structured_rectangle(0.3, 0.03, 30, 3);
  const P2Space space(mesh);
  const Mesh nodal = nodal_mesh(space);
  const SparseMatrix K = assemble_elasticity(space, Lame::from_young_poisson(3e5, 0.45));
  const ContactConstraint contact = assemble_contact(nodal, nodal.label("bottom"), FlatFoundation(-0.01));
  const std::vector<int> fixed = clamped_dofs(space, mesh.label("left"));
  std::vector<int> free;
  for (int d = 0; d < K.rows(); ++d)
    if (!std::binary_search(fixed.begin(), fixed.end(), d)) free.push_back(d);
  SparseMatrix P(K.rows(), static_cast<int>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) P.insert(free[k], static_cast<int>(k)) = 1.0;
  return {P.transpose() * K * P, contact.C_S * P};
}

TEST(BoundaryLastCholesky, SolvesAndTheSchurComplementAreThePlainFactorisations) {
  const Problem p = beam();
  ASSERT_GT(p.C.rows(), 20);
  BoundaryLastCholesky f;
  f.analyse(p.A, p.C);
  ASSERT_TRUE(f.factorize(p.A));
  ASSERT_TRUE(f.fits(p.A, p.C));
  const Eigen::SimplicialLLT<SparseMatrix> plain(p.A);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(p.A.rows(), -1.0, 2.0);
  const Eigen::VectorXd x = f.solve(b), y = plain.solve(b);
  EXPECT_LT((x - y).cwiseAbs().maxCoeff(), 1e-10 * y.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd Ct = Eigen::MatrixXd(SparseMatrix(p.C.transpose()));
  const Eigen::MatrixXd S_plain = p.C * Eigen::MatrixXd(plain.solve(Ct));
  const Eigen::MatrixXd S = f.schur(p.C);
  EXPECT_LT((S - S_plain).cwiseAbs().maxCoeff(), 1e-10 * S_plain.cwiseAbs().maxCoeff());
  // Refactorised with another matrix of the same pattern (a Newton step's tangent).
  const SparseMatrix A2 = 1.7 * p.A;
  ASSERT_TRUE(f.factorize(A2));
  EXPECT_LT((f.schur(p.C) - S_plain / 1.7).cwiseAbs().maxCoeff(), 1e-10 * S_plain.cwiseAbs().maxCoeff());
  // A constraint touching another column is not this factor's.
  SparseMatrix other = p.C;
  other.coeffRef(0, 0) += 1.0;
  EXPECT_FALSE(f.touches_only_constrained(other));
  EXPECT_THROW(f.schur(other), std::logic_error);
}

TEST(BoundaryLastCholesky, FillStaysNearAmdsOnTheWholeMatrix) {
  const Problem p = beam();
  BoundaryLastCholesky f;
  f.analyse(p.A, p.C);
  ASSERT_TRUE(f.factorize(p.A));
  const Eigen::SimplicialLLT<SparseMatrix> plain(p.A);
  const auto ours = f.factor_nonzeros(), amd = static_cast<Eigen::Index>(SparseMatrix(plain.matrixL()).nonZeros());
  std::printf("factor nonzeros: boundary last %ld, AMD %ld\n", static_cast<long>(ours), static_cast<long>(amd));
  EXPECT_LT(ours, 2 * amd);
}

}  // namespace
}  // namespace fsi::boundary_last_cholesky_test
