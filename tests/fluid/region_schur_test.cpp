// The substructured fluid solve (RegionSchurSolver behind PenalisedStokes with
// FluidFactorization::schur) gives the whole-matrix solve's solution, through χ
// changes inside the near region (no new far-field factorisation), a χ that leaves
// it (a new region) and a new ε; a χ covering most of D falls back to the whole solve.
#include <gtest/gtest.h>

#include <memory>

#include "common/errors.hpp"

#include "fluid/fluid_field.hpp"
#include "fluid/penalised_stokes.hpp"
#include "fem/point_locator.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::region_schur_test {
namespace {

struct Box {
  explicit Box(int n = 16) : mesh(testing::structured_rectangle(1.0, 1.0, n, n)) {}
  Mesh mesh;
  // χ = 1 on the triangles whose barycentre lies in [x0, x0 + w] × [y0, y0 + h].
  Eigen::VectorXd block(double x0, double y0, double w, double h) const {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(mesh.num_triangles());
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      Point m = Point::Zero();
      for (int v : mesh.triangles[t]) m += mesh.vertices[v] / 3.0;
      if (m.x() > x0 && m.x() < x0 + w && m.y() > y0 && m.y() < y0 + h) c[t] = 1.0;
    }
    return c;
  }
  static Point gravity(const Point& x) { return Point(x.y(), -9.81); }
  std::unique_ptr<PenalisedStokes> stokes(double eps, FluidFactorization f, double far_budget_mb = INFINITY,
                                          const VectorField& force = gravity) const {
    FluidBoundaryConditions bc;
    for (const char* name : {"left", "bottom", "top"}) bc.dirichlet_labels.push_back(mesh.label(name));
    bc.g = [](const Point& x) { return x.y() > 1 - 1e-12 ? Point(x.x() * (1 - x.x()), 0) : Point(0, 0); };
    bc.tractions.push_back({mesh.label("right"), [](const Point& x) { return Point(-x.y(), 0.5); }});
    auto s = std::make_unique<PenalisedStokes>(mesh, 0.01, eps, force, bc);
    s->set_factorization(f, far_budget_mb);
    return s;
  }
};

// The triangles of χ's support: where a structure there samples the fields.
std::vector<int> support(const Eigen::VectorXd& chi) {
  std::vector<int> triangles;
  for (Eigen::Index t = 0; t < chi.size(); ++t)
    if (chi[t] != 0) triangles.push_back(static_cast<int>(t));
  return triangles;
}

double relative_difference(const FluidSolution& a, const FluidSolution& b) {
  const double scale = a.v1.norm() + a.v2.norm() + a.p.norm() + a.bubble.norm();
  return ((a.v1 - b.v1).norm() + (a.v2 - b.v2).norm() + (a.p - b.p).norm() + (a.bubble - b.bubble).norm()) /
         scale;
}

// b, a near-only solution, equals the whole solve's a on the triangles it marks exact
// (velocity and pressure at their centres, bubbles included) and is refused by
// FluidField on the others; there are both kinds.
void expect_exact_near_only(const Mesh& mesh, const FluidSolution& a, const FluidSolution& b) {
  ASSERT_NE(b.exact_on, nullptr);
  const PointLocator locator(mesh);
  const FluidField fa(locator, a), fb(locator, b);
  int near = 0, far = 0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const Location centre{t, Eigen::Vector3d::Constant(1.0 / 3)};
    if ((*b.exact_on)[t]) {
      ++near;
      EXPECT_LT((fa.at(centre).v - fb.at(centre).v).norm(), 1e-10 * (1 + fa.at(centre).v.norm())) << t;
      EXPECT_NEAR(fa.at(centre).p, fb.at(centre).p, 1e-10 * (1 + std::abs(fa.at(centre).p))) << t;
    } else {
      ++far;
      EXPECT_THROW(fb.at(centre), FieldNotComputed) << t;
    }
  }
  EXPECT_GT(near, 0);
  EXPECT_GT(far, 0);
}

TEST(RegionSchur, GivesTheWholeSolveThroughChiChangesARegionChangeAndANewEps) {
  const Box box;
  auto whole = box.stokes(1e-5, FluidFactorization::whole);
  auto schur = box.stokes(1e-5, FluidFactorization::schur);
  struct Step {
    Eigen::VectorXd chi;
    double eps;
    int regions;  // far-field factorisations so far
  };
  const std::vector<Step> steps = {
      {box.block(0.30, 0.40, 0.30, 0.15), 1e-5, 1},
      {box.block(0.32, 0.37, 0.30, 0.15), 1e-5, 1},  // a small move: the same region
      {box.block(0.34, 0.35, 0.30, 0.16), 1e-7, 1},  // and a new ε
      {box.block(0.05, 0.75, 0.20, 0.15), 1e-7, 2},  // far away: a new region
  };
  for (std::size_t k = 0; k < steps.size(); ++k) {
    whole->set_chi(steps[k].chi), whole->set_eps(steps[k].eps);
    schur->set_chi(steps[k].chi), schur->set_eps(steps[k].eps);
    const FluidSolution& a = whole->solve();
    const FluidSolution& b = schur->solve();
    EXPECT_LT(relative_difference(a, b), 1e-10) << "step " << k;
    EXPECT_EQ(schur->timing().regions, steps[k].regions) << "step " << k;
    EXPECT_EQ(schur->timing().factorizations, static_cast<int>(k) + 1) << "step " << k;
  }
  ASSERT_NE(schur->region(), nullptr);
  EXPECT_GT(schur->region()->interface_unknowns(), 0);
  EXPECT_LT(schur->region()->near_unknowns(), schur->unknowns() / 2);
}

// A solve that needs the fields only where χ is (as the coupling's, sampled at the
// structure's vertices): exact on the near region (bubbles included), refused
// elsewhere by FluidField; solution() gives the whole solution; a sampled triangle
// beyond the region expands at once; a new region completes the last solution first.
TEST(RegionSchur, SolvesAreExactWhereSampledAndCompleteOnDemand) {
  const Box box;
  auto whole = box.stokes(1e-5, FluidFactorization::whole);
  auto schur = box.stokes(1e-5, FluidFactorization::schur);
  const Eigen::VectorXd chi = box.block(0.30, 0.40, 0.30, 0.15);
  const std::vector<int> inside = support(chi);
  whole->set_chi(chi), schur->set_chi(chi);
  const FluidSolution& a = whole->solve();
  const FluidSolution& b = schur->solve(&inside);
  expect_exact_near_only(box.mesh, a, b);
  EXPECT_EQ(schur->timing().factorizations, 1);
  EXPECT_EQ(schur->timing().expansion, 0.0);
  const FluidSolution& c = schur->solution();
  EXPECT_EQ(c.exact_on, nullptr);
  EXPECT_LT(relative_difference(a, c), 1e-10);
  EXPECT_EQ(schur->timing().factorizations, 1);  // completing refactorises nothing
  EXPECT_GT(schur->timing().expansion, 0.0);

  // Sampled beyond the near region (the far corner): the solve expands at once.
  const Eigen::VectorXd nudged = box.block(0.31, 0.40, 0.30, 0.15);
  std::vector<int> reaching = support(nudged);
  reaching.push_back(0);
  whole->set_chi(nudged), schur->set_chi(nudged);
  ASSERT_FALSE(schur->region()->near_mask()[0]);
  const FluidSolution& d = schur->solve(&reaching);
  EXPECT_EQ(d.exact_on, nullptr);
  EXPECT_LT(relative_difference(whole->solve(), d), 1e-10);
  EXPECT_EQ(schur->timing().regions, 1);

  // Near the structure only again, then χ moves out of the region: the new region's
  // set-up first completes the previous solution; the result is the whole solve's.
  const Eigen::VectorXd moved = box.block(0.05, 0.75, 0.20, 0.15);
  whole->set_chi(moved), schur->set_chi(moved);
  schur->solve(&inside);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_EQ(schur->timing().regions, 2);
}

// Far factors over the memory budget (here: any) are released once S is known; each
// expansion refactorises the far field and releases the near factors, which the
// next solve redoes. The solutions are the same; a solution left near-only when its
// region is replaced is not completed (that would cost a factorisation) but stays
// exact near the structure.
TEST(RegionSchur, ReleasedFarFactorsGiveTheSameSolutions) {
  const Box box;
  auto whole = box.stokes(1e-5, FluidFactorization::whole);
  auto schur = box.stokes(1e-5, FluidFactorization::schur, /*far_budget_mb=*/0);
  const std::vector<Eigen::VectorXd> chis = {box.block(0.30, 0.40, 0.30, 0.15), box.block(0.32, 0.37, 0.30, 0.15),
                                             box.block(0.34, 0.35, 0.30, 0.16)};
  for (std::size_t k = 0; k < chis.size(); ++k) {
    whole->set_chi(chis[k]), schur->set_chi(chis[k]);
    EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10) << "step " << k;
    EXPECT_EQ(schur->timing().regions, 1);
    EXPECT_EQ(schur->timing().far_refactorizations, static_cast<int>(k) + 1);  // one per expansion
  }
  ASSERT_NE(schur->region(), nullptr);
  EXPECT_FALSE(schur->region()->keeps_far_factors());
  EXPECT_GT(schur->region()->far_factor_mb(), 0);

  // A near-only solve, then a χ outside the region: the new region leaves the
  // previous solution as it was (no refactorisation); the new solve is exact.
  const Eigen::VectorXd last = box.block(0.36, 0.33, 0.30, 0.16);
  whole->set_chi(last), schur->set_chi(last);
  const FluidSolution& a = whole->solve();
  const std::vector<int> inside = support(last);
  schur->solve(&inside);
  const Eigen::VectorXd moved = box.block(0.05, 0.75, 0.20, 0.15);
  schur->set_chi(moved);
  schur->set_eps(1e-6);  // settles the pending expansion the same way
  EXPECT_EQ(schur->timing().far_refactorizations, 3);
  const FluidSolution& old = schur->solution(&inside);
  expect_exact_near_only(box.mesh, a, old);
  // Everywhere, it cannot be had any more (its far factors were released): said,
  // not drawn from stale values.
  EXPECT_THROW(schur->solution(), SolverFailure);
  EXPECT_EQ(schur->timing().far_refactorizations, 3);
  whole->set_chi(moved), whole->set_eps(1e-6);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_EQ(schur->timing().regions, 2);
  EXPECT_EQ(schur->timing().far_refactorizations, 4);
}

// A hint of where χ will go makes the first region cover it: a χ that moves there
// needs no second far-field factorisation (without the hint it does, as in the
// first test), and the solution is still the whole solve's.
TEST(RegionSchur, AHintOfWhereChiGoesSavesTheSecondRegion) {
  const Box box(32);
  auto whole = box.stokes(1e-5, FluidFactorization::whole);
  auto schur = box.stokes(1e-5, FluidFactorization::schur);
  const Eigen::VectorXd start = box.block(0.44, 0.62, 0.12, 0.08), end = box.block(0.44, 0.15, 0.12, 0.08);
  schur->expect_chi(end);
  for (const Eigen::VectorXd* chi : {&start, &end}) {
    whole->set_chi(*chi), schur->set_chi(*chi);
    EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  }
  EXPECT_EQ(schur->timing().regions, 1);
  ASSERT_NE(schur->region(), nullptr);  // substructured, not the whole fallback

  auto unhinted = box.stokes(1e-5, FluidFactorization::schur);
  for (const Eigen::VectorXd* chi : {&start, &end}) unhinted->set_chi(*chi), unhinted->solve();
  EXPECT_EQ(unhinted->timing().regions, 2);
  ASSERT_NE(unhinted->region(), nullptr);
}

// Whether every triangle of χ's support is in the near region in use.
bool region_covers(const PenalisedStokes& s, const Eigen::VectorXd& chi) {
  if (!s.region()) return false;
  for (Eigen::Index t = 0; t < chi.size(); ++t)
    if (chi[t] != 0 && !s.region()->near_mask()[static_cast<std::size_t>(t)]) return false;
  return true;
}

// A sweep reuses one PenalisedStokes across rows, reset() and a new ε between them.
// A hint given after reset() is honoured: the region kept from the last row does
// not cover it, so it is dropped and the row's first region covers the hint (χ
// then moves there without a second far-field factorisation). A hint the kept
// region covers keeps it: the row needs no far-field factorisation at all.
TEST(RegionSchur, AHintGivenAfterResetIsHonoured) {
  const Box box(32);
  auto whole = box.stokes(1e-5, FluidFactorization::whole);
  auto schur = box.stokes(1e-5, FluidFactorization::schur);
  const Eigen::VectorXd first_row = box.block(0.05, 0.75, 0.12, 0.08);
  schur->expect_chi(first_row);
  schur->set_chi(first_row);
  schur->solve();
  ASSERT_NE(schur->region(), nullptr);

  const Eigen::VectorXd start = box.block(0.44, 0.62, 0.12, 0.08),
                        end = box.block(0.44, 0.15, 0.12, 0.08);
  ASSERT_FALSE(region_covers(*schur, end));
  schur->reset(), schur->set_eps(1e-6), whole->set_eps(1e-6);
  schur->expect_chi(end);
  schur->set_chi(start), whole->set_chi(start);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_TRUE(region_covers(*schur, end)) << "the first region of the row ignores the hint";
  schur->set_chi(end), whole->set_chi(end);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_EQ(schur->timing().regions, 1);
  EXPECT_NE(schur->region(), nullptr) << "solved whole: the region grew too large";

  schur->reset(), schur->set_eps(1e-5), whole->set_eps(1e-5);
  schur->expect_chi(end);  // covered: the region is kept
  schur->set_chi(start), whole->set_chi(start);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  schur->set_chi(end), whole->set_chi(end);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_EQ(schur->timing().regions, 0);
}

// A new load with the same χ (every step of a time-dependent run) is solved again, by
// either factorisation, and gives a fresh solver's solution (issue 28: the fluid was
// built on "only χ changes" and would have returned the old solution).
TEST(RegionSchur, ANewLoadWithTheSameChiIsSolvedAgain) {
  const Box box;
  const Eigen::VectorXd chi = box.block(0.3, 0.3, 0.2, 0.2);
  const VectorField other = [](const Point& x) { return Point(3.0 * x.x(), -2.0); };
  for (const FluidFactorization f : {FluidFactorization::whole, FluidFactorization::schur}) {
    auto s = box.stokes(1e-4, f);
    s->set_chi(chi);
    s->solve();
    const FluidSolution first = s->solution();
    s->set_body_force(other);
    s->set_chi(chi);
    s->solve();
    const FluidSolution second = s->solution();
    EXPECT_EQ(s->timing().reused, 0);
    EXPECT_GT(relative_difference(first, second), 0.1) << "the old solution came back";
    auto fresh = box.stokes(1e-4, f, INFINITY, other);
    fresh->set_chi(chi);
    fresh->solve();
    EXPECT_LT(relative_difference(fresh->solution(), second), 1e-10);
    s->solve();  // nothing changed since: reused
    EXPECT_EQ(s->timing().reused, 1);
  }
}

// A new load keeps the far field's factors (its new load condensed: a time step's
// history, an inflow in time); a new operator there (another viscous form) or far
// factors released between expansions factorise the region again. Each answer is a
// fresh solve's.
TEST(RegionSchur, ANewLoadKeepsTheFarFactorsAndANewOperatorRefactorises) {
  const Box box;
  const Eigen::VectorXd chi = box.block(0.3, 0.3, 0.2, 0.2);
  const VectorField other = [](const Point& x) { return Point(3.0 * x.x(), -2.0); };
  auto fresh = [&](ViscousForm form) {
    auto f = box.stokes(1e-4, FluidFactorization::whole, INFINITY, other);
    f->set_viscous_form(form);
    f->set_chi(chi);
    return FluidSolution(f->solve());
  };
  auto s = box.stokes(1e-4, FluidFactorization::schur);
  s->set_chi(chi);
  s->solve();
  ASSERT_EQ(s->timing().regions, 1);
  s->set_body_force(other);
  EXPECT_LT(relative_difference(fresh(ViscousForm::symmetric), s->solve()), 1e-10);
  EXPECT_EQ(s->timing().regions, 1) << "a new load refactorised the far field";
  s->set_viscous_form(ViscousForm::gradient);
  EXPECT_LT(relative_difference(fresh(ViscousForm::gradient), s->solve()), 1e-10);
  EXPECT_EQ(s->timing().regions, 2) << "a new far operator kept the old factors";

  auto released = box.stokes(1e-4, FluidFactorization::schur, 0.0);  // no far factors kept
  released->set_chi(chi);
  released->solve();
  released->set_body_force(other);
  EXPECT_LT(relative_difference(fresh(ViscousForm::symmetric), released->solve()), 1e-10);
  EXPECT_EQ(released->timing().regions, 2);
}

TEST(RegionSchur, FallsBackToTheWholeSolveWhenChiCoversMostOfTheDomain) {
  const Box box;
  auto whole = box.stokes(1e-4, FluidFactorization::whole);
  auto schur = box.stokes(1e-4, FluidFactorization::schur);
  const Eigen::VectorXd chi = box.block(0.1, 0.1, 0.8, 0.8);
  whole->set_chi(chi), schur->set_chi(chi);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-10);
  EXPECT_EQ(schur->region(), nullptr);
  EXPECT_EQ(schur->timing().regions, 0);
}

TEST(RegionSchur, WithoutAStructureSolvesWhole) {
  const Box box;
  auto whole = box.stokes(1e-4, FluidFactorization::whole);
  auto schur = box.stokes(1e-4, FluidFactorization::schur);
  EXPECT_LT(relative_difference(whole->solve(), schur->solve()), 1e-12);
  EXPECT_EQ(schur->region(), nullptr);
}

}  // namespace
}  // namespace fsi::region_schur_test
