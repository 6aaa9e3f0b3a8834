// MumpsSchur against dense linear algebra on a penalised Stokes matrix: the Schur
// complement on an interface, the condensed right-hand side, the expansion (also
// repeated for several x_Γ after one condensation, as the fluid solver uses it).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "fluid/mumps_schur.hpp"
#include "fluid/penalised_stokes.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::mumps_schur_test {
namespace {

TEST(MumpsSchur, EqualsTheDenseSchurComplementAndSolvesThroughIt) {
  const Mesh mesh = testing::structured_rectangle(1.0, 1.0, 10, 10);
  FluidBoundaryConditions bc;
  for (const char* name : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(name));
  bc.g = [](const Point& x) { return x.y() > 1 - 1e-12 ? Point(x.x() * (1 - x.x()), 0) : Point(0, 0); };
  PenalisedStokes stokes(mesh, 0.01, 1e-5, [](const Point&) { return Point(0, -9.81); }, bc);
  Eigen::VectorXd chi = Eigen::VectorXd::Zero(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); t += 7) chi[t] = 1.0;
  stokes.set_chi(chi);
  stokes.assemble_full();
  const Eigen::SparseMatrix<double>& K = stokes.matrix();
  const Eigen::VectorXd& b = stokes.rhs();
  const int n = static_cast<int>(K.rows());
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);

  // Γ: every third unknown, from the end (a scrambled, non-contiguous list).
  std::vector<int> gamma, F;
  std::vector<char> in_gamma(n, 0);
  for (int i = n - 1; i >= 0; i -= 3) gamma.push_back(i), in_gamma[i] = 1;
  for (int i = 0; i < n; ++i)
    if (!in_gamma[i]) F.push_back(i);
  const int ng = static_cast<int>(gamma.size()), nf = static_cast<int>(F.size());
  Eigen::MatrixXd K_FF(nf, nf), K_FG(nf, ng), K_GG(ng, ng);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j) K_FF(i, j) = Kd(F[i], F[j]);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < ng; ++j) K_FG(i, j) = Kd(F[i], gamma[j]);
  for (int i = 0; i < ng; ++i)
    for (int j = 0; j < ng; ++j) K_GG(i, j) = Kd(gamma[i], gamma[j]);
  Eigen::VectorXd b_F(nf), b_G(ng);
  for (int i = 0; i < nf; ++i) b_F[i] = b[F[i]];
  for (int i = 0; i < ng; ++i) b_G[i] = b[gamma[i]];
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K_FF);
  const Eigen::MatrixXd S = K_GG - K_FG.transpose() * lu.solve(K_FG);
  const Eigen::VectorXd y = b_G - K_FG.transpose() * lu.solve(b_F);

  MumpsSchur schur;
  schur.factorize(K, gamma);
  EXPECT_LT((schur.schur() - S).norm(), 1e-10 * S.norm());
  const Eigen::VectorXd y_mumps = schur.condense(b);
  EXPECT_LT((y_mumps - y).norm(), 1e-10 * y.norm());

  // Through the Schur complement to the solution of K x = b.
  const Eigen::VectorXd x_G = schur.schur().partialPivLu().solve(y_mumps);
  const Eigen::VectorXd x = schur.expand(x_G);
  const Eigen::VectorXd x_ref = Kd.partialPivLu().solve(b);
  EXPECT_LT((x - x_ref).norm(), 1e-10 * x_ref.norm());
  for (int i = 0; i < ng; ++i) EXPECT_EQ(x[gamma[i]], x_G[i]);

  // Repeated expansions after one condensation: x_F = K_FF⁻¹ (b_F − K_FΓ x_Γ).
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd z_G = Eigen::VectorXd::Random(ng);
    const Eigen::VectorXd z = schur.expand(z_G);
    const Eigen::VectorXd z_F = lu.solve(b_F - K_FG * z_G);
    Eigen::VectorXd got_F(nf);
    for (int i = 0; i < nf; ++i) got_F[i] = z[F[i]];
    EXPECT_LT((got_F - z_F).norm(), 1e-10 * z_F.norm()) << "trial " << trial;
  }

  // Released: S stays, the factors go (no condensation or expansion without them);
  // a new factorisation gives the same numbers, bit for bit.
  const Eigen::MatrixXd S_before = schur.schur();
  EXPECT_GT(schur.factor_memory_mb(), 0);
  schur.release();
  EXPECT_FALSE(schur.has_factors());
  EXPECT_EQ(schur.schur(), S_before);
  EXPECT_THROW(schur.condense(b), std::logic_error);
  EXPECT_THROW(schur.expand(x_G), std::logic_error);
  schur.factorize(K, gamma);
  EXPECT_TRUE(schur.has_factors());
  EXPECT_EQ(schur.schur(), S_before);
  EXPECT_EQ(schur.condense(b), y_mumps);
  EXPECT_EQ(schur.expand(x_G), x);
}

TEST(MumpsSchur, RefusesAnEmptyOrFullInterface) {
  Eigen::SparseMatrix<double> A(3, 3);
  A.setIdentity();
  A.makeCompressed();
  MumpsSchur schur;
  EXPECT_THROW(schur.factorize(A, {}), std::invalid_argument);
  EXPECT_THROW(schur.factorize(A, {0, 1, 2}), std::invalid_argument);
  EXPECT_THROW(schur.factorize(A, {1, 1}), std::invalid_argument);
  EXPECT_THROW(schur.condense(Eigen::VectorXd::Ones(3)), std::logic_error);
}

}  // namespace
}  // namespace fsi::mumps_schur_test
