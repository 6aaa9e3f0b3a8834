// FixedPointLoop around a coupled map that is not a fluid (coupling/coupled_map.hpp):
// H(u) = A_S⁻¹ (b + c A_S u) = A_S⁻¹ b + c u, the structure's own QP (no obstacle), a
// scaled identity with a known fixed point u* = A_S⁻¹ b / (1 − c). The loop needs
// nothing of the fluid: constant ω converges at the rate 1 − ω(1 − c), Aitken's secant
// step is exact for it; after Relaxation::end_window() a second window (another b)
// starts again from ω0, as a time loop would drive it.
#include "coupling/fixed_point_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/case.hpp"
#include "run/structure_setup.hpp"

namespace fsi::fixed_point_loop_test {
namespace {

class LinearMap final : public CoupledMap {
 public:
  LinearMap(ElasticContactSolver& s, Eigen::VectorXd b, double c) : s_(s), b_(std::move(b)), c_(c) {}
  MapValue operator()(const Eigen::VectorXd& u, int, const ContactSolution* warm, IterationRecord&) override {
    ++evaluations;
    MapValue v;
    v.structure = s_.solve(b_ + c_ * (s_.A_S() * u), warm);
    v.fluid_load = c_ * (s_.A_S() * u);
    return v;
  }
  std::string describe(const IterationRecord&) const override { return "linear map"; }
  ElasticContactSolver& structure() override { return s_; }
  int evaluations = 0;

 private:
  ElasticContactSolver& s_;
  Eigen::VectorXd b_;
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
  LinearMap H(*s.solver, s.b_applied, c);
  const Eigen::VectorXd u_star = s.solver->solve(s.b_applied).u / (1 - c);
  const SparseMatrix M = assemble_vector_mass(s.mesh());
  const double scale = std::sqrt(u_star.dot(M * u_star));
  std::vector<std::string> lines;
  auto constant = make_relaxation("constant", {.omega0 = 0.5}, M);
  FixedPointLoop loop(H, *constant, M, 1e-10 * scale, 100);
  loop.progress = [&](const std::string& line) { lines.push_back(line); };
  const CouplingResult r = loop.run({});
  ASSERT_TRUE(r.converged) << r.failure;
  // Contraction 1 − ω(1 − c) = 0.25 per pass: about log(1e-10)/log(0.25) ≈ 17 passes.
  EXPECT_GE(r.iterations, 14);
  EXPECT_LE(r.iterations, 20);
  EXPECT_LT((r.structure.u - u_star).cwiseAbs().maxCoeff(), 1e-9 * u_star.cwiseAbs().maxCoeff());
  ASSERT_EQ(static_cast<int>(lines.size()), r.iterations);
  EXPECT_NE(lines[0].find("[coupling] it   1: increment"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("linear map"), std::string::npos) << lines[0];
  EXPECT_EQ(r.history.size(), static_cast<std::size_t>(r.iterations));
}

TEST(FixedPointLoop, AitkenIsExactForAScaledIdentityInEachWindow) {
  StructureSetup s = free_beam();
  const SparseMatrix M = assemble_vector_mass(s.mesh());
  auto aitken = make_relaxation("aitken", {.omega0 = 0.1}, M);
  for (double load : {1.0, 2.0}) {  // two windows, the second with twice the load
    LinearMap H(*s.solver, load * s.b_applied, -0.5);
    const Eigen::VectorXd u_star = s.solver->solve(load * s.b_applied).u / 1.5;
    const double tol = 1e-10 * std::sqrt(u_star.dot(M * u_star));
    FixedPointLoop loop(H, *aitken, M, tol, 50);
    const CouplingResult r = loop.run({});
    ASSERT_TRUE(r.converged) << r.failure;
    EXPECT_LE(r.iterations, 4) << "window with load " << load;  // ω0 step, the secant step, the check
    EXPECT_NEAR(aitken->omega(), 2.0 / 3.0, 1e-9);             // 1/(1 − c)
    EXPECT_NEAR(r.history[0].omega, 0.1, 1e-15);               // each window starts from ω0
    aitken->end_window();
  }
}

}  // namespace
}  // namespace fsi::fixed_point_loop_test
