// FixedPointCoupling around a fluid step that is not a fluid (coupling/coupled_map.hpp):
// the load c A_S u, so that H(u) = A_S⁻¹ (b + c A_S u) = A_S⁻¹ b + c u with the
// structure's own QP (no obstacle), a scaled identity with a known fixed point
// u* = A_S⁻¹ b / (1 − c). The loop needs nothing of the fluid: constant ω converges at
// the rate 1 − ω(1 − c), Aitken's secant step is exact for it; the next window (another
// b, from the last window's state) starts again from ω0, as a time loop will drive it.
#include "coupling/fixed_point.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/case.hpp"
#include "run/structure_setup.hpp"

namespace fsi::fixed_point_loop_test {
namespace {

class LinearFluid final : public FluidStep {
 public:
  LinearFluid(const ElasticContactSolver& s, double c) : s_(s), c_(c) {}
  Eigen::VectorXd load(const Eigen::VectorXd& u, int, IterationRecord&) override {
    ++evaluations;
    return c_ * (s_.A_S() * u);
  }
  std::string describe(const IterationRecord&) const override { return "linear map"; }
  int evaluations = 0;

 private:
  const ElasticContactSolver& s_;
  double c_;
};

StructureSetup free_beam() {
  const Case c = load_case_text(R"(name = "beam"
obstacles = []
[structure]
L = 0.06
H = 0.005
E = 3.0e5
nu = 0.3
f = [0.0, -1.0e4]
h = 0.002
[contact]
gap = "normal"
boundary = "all"
)", "beam.toml");
  return make_structure(c, make_structure_mesh(c), nullptr);
}

TEST(FixedPointLoop, IteratesAnyCoupledMapToItsFixedPoint) {
  StructureSetup s = free_beam();
  const double c = -0.5;
  LinearFluid fluid(*s.solver, c);
  StructureStep structure(*s.solver);
  const Eigen::VectorXd u_star = s.solver->solve(s.b_applied).u / (1 - c);
  const SparseMatrix M = assemble_vector_mass(s.mesh());
  const double scale = std::sqrt(u_star.dot(M * u_star));
  std::vector<std::string> lines;
  auto constant = make_relaxation("constant", {.omega0 = 0.5}, M);
  FixedPointCoupling loop(fluid, structure, s.b_applied, *constant, M, 1e-10 * scale, 100);
  loop.progress = [&](const std::string& line) { lines.push_back(line); };
  const CouplingResult r = loop.run();
  ASSERT_TRUE(r.converged) << r.failure;
  // Contraction 1 − ω(1 − c) = 0.25 per pass: about log(1e-10)/log(0.25) ≈ 17 passes.
  EXPECT_GE(r.iterations, 14);
  EXPECT_LE(r.iterations, 20);
  EXPECT_LT((r.structure.u - u_star).cwiseAbs().maxCoeff(), 1e-9 * u_star.cwiseAbs().maxCoeff());
  ASSERT_EQ(static_cast<int>(lines.size()), r.iterations);
  EXPECT_NE(lines[0].find("[coupling] it   1: increment"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("linear map"), std::string::npos) << lines[0];
  EXPECT_EQ(r.history.size(), static_cast<std::size_t>(r.iterations));
  EXPECT_EQ(fluid.evaluations, r.iterations);
}

TEST(FixedPointLoop, AitkenIsExactForAScaledIdentityInEachWindow) {
  StructureSetup s = free_beam();
  const SparseMatrix M = assemble_vector_mass(s.mesh());
  auto aitken = make_relaxation("aitken", {.omega0 = 0.1}, M);
  LinearFluid fluid(*s.solver, -0.5);
  StructureStep structure(*s.solver);
  Eigen::VectorXd b = s.b_applied;
  const Eigen::VectorXd u_star = s.solver->solve(b).u / 1.5;
  const double tol = 1e-10 * std::sqrt(u_star.dot(M * u_star));
  FixedPointCoupling loop(fluid, structure, b, *aitken, M, tol, 50);
  CouplingResult r = loop.run();
  for (double load : {1.0, 2.0}) {  // two windows, the second with twice the load
    if (load > 1) {
      b = load * s.b_applied;  // the window's new data (a time step's)
      r = loop.next_window(r.structure.u);
    }
    ASSERT_TRUE(r.converged) << r.failure;
    EXPECT_LE(r.iterations, 4) << "window with load " << load;  // ω0 step, the secant step, the check
    EXPECT_NEAR(aitken->omega(), 2.0 / 3.0, 1e-9);             // 1/(1 − c)
    EXPECT_NEAR(r.history[0].omega, 0.1, 1e-15);               // each window starts from ω0
    EXPECT_LT((r.structure.u - load * u_star).cwiseAbs().maxCoeff(), 1e-8 * load * u_star.cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace fsi::fixed_point_loop_test
