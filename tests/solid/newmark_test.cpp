// Newmark's average acceleration for the structure (SPEC §12, solid/newmark.hpp) and its
// mass matrices (solid/structure_mass.hpp): the masses' totals; without contact the
// discrete energy ½vᵀMv + ½uᵀA_S u − bᵀu kept to round-off for a linear material, and
// order 2 in time against a run with a step 64 times shorter; a free body moved
// rigidly by its initial velocity; a hyperelastic beam's Newton steps with inertia.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "qp/active_set_solver.hpp"
#include "solid/newmark.hpp"
#include "solid/p2_elasticity.hpp"
#include "solid/structure_mass.hpp"
#include "support/structured_mesh.hpp"

namespace fsi::newmark_test {
namespace {

const Lame kLame = Lame::from_young_poisson(1.0e4, 0.3);
constexpr double kRho = 10.0;

ContactConstraint no_contact(int dofs) { return {SparseMatrix(0, dofs), Eigen::VectorXd(0), {}}; }

double total_mass(const SparseMatrix& M) { return Eigen::VectorXd::Ones(M.rows()).dot(M * Eigen::VectorXd::Ones(M.rows())) / 2; }

TEST(StructureMass, EveryMassMatrixCarriesTheBodysMass) {
  const Mesh mesh = testing::structured_rectangle(2.0, 0.5, 8, 3, true);
  const double mass = kRho * 2.0 * 0.5;
  EXPECT_NEAR(total_mass(consistent_mass(mesh, nullptr, kRho)), mass, 1e-12);
  const P2Space p2(mesh);
  EXPECT_NEAR(total_mass(consistent_mass(mesh, &p2, kRho)), mass, 1e-12);
  // The left side's vertices and a corner that has no neighbour off the boundary.
  std::vector<int> massless = mesh.vertices_on(mesh.label("left"));
  const SparseMatrix R = redistributed_mass(mesh, massless, kRho);
  EXPECT_NEAR(total_mass(R), mass, 1e-12);
  for (int v : massless) EXPECT_EQ(R.coeff(v, v), 0.0) << v;
  for (int d = 0; d < R.rows(); ++d) EXPECT_GE(R.coeff(d, d), 0.0);
  // Every vertex massless: nothing to carry the mass.
  std::vector<int> all(static_cast<std::size_t>(mesh.num_vertices()));
  for (int v = 0; v < mesh.num_vertices(); ++v) all[v] = v;
  EXPECT_THROW(redistributed_mass(mesh, all, kRho), std::invalid_argument);
}

// A cantilever (clamped on the left) from rest under a constant load, n steps to T.
struct Cantilever {
  Mesh mesh = testing::structured_rectangle(1.0, 0.1, 20, 2);
  ActiveSetSolver qp;
  SparseMatrix M;
  std::unique_ptr<ElasticContactSolver> solver;
  std::unique_ptr<Newmark> newmark;
  Eigen::VectorXd b;

  double dt;
  std::function<double(double)> ramp = [](double) { return 1.0; };  // the load's factor in time

  explicit Cantilever(double dt_, bool clamped = true, double gravity = 50.0) : dt(dt_) {
    M = consistent_mass(mesh, nullptr, kRho);
    const Inertia inertia{M, Newmark::operator_factor(dt)};
    const std::vector<int> fixed = clamped ? clamped_dofs(mesh, mesh.label("left")) : std::vector<int>{};
    solver = std::make_unique<ElasticContactSolver>(mesh, kLame, no_contact(2 * mesh.num_vertices()), -1, fixed, qp,
                                                     nullptr, &inertia);
    newmark = std::make_unique<Newmark>(M, dt, solver->free_dofs());
    b = assemble_volume_load(mesh, [gravity](const Point&) { return Point(0.0, -gravity); }, 1);
  }
  NewmarkState run(int steps, Eigen::VectorXd v0, std::vector<double>* energy = nullptr) {
    const int n = 2 * mesh.num_vertices();
    NewmarkState s = newmark->start(0.0, Eigen::VectorXd::Zero(n), std::move(v0), ramp(0) * b, solver->at_rest());
    for (int k = 0; k < steps; ++k) {
      s = newmark->advance(s, solver->solve(newmark->effective_load(s, ramp((k + 1) * dt) * b), &s.contact));
      if (energy) energy->push_back(newmark->kinetic_energy(s.v) + elastic_energy(*solver, s.u) - b.dot(s.u));
    }
    return s;
  }
};

// From rest under a constant load: E = ½vᵀMv + ½uᵀA_S u − bᵀu stays 0, to round-off
// of the energies that swap (the load's work at its largest).
TEST(Newmark, KeepsTheEnergyOfALinearStructureToRoundOff) {
  Cantilever beam(0.01);
  std::vector<double> energy;
  const NewmarkState s = beam.run(400, Eigen::VectorXd::Zero(2 * beam.mesh.num_vertices()), &energy);
  double drift = 0;
  for (double e : energy) drift = std::max(drift, std::abs(e));
  const double work = std::abs(beam.b.dot(s.u));
  ASSERT_GT(work, 0);
  // 400 steps of round-off in A + (4/Δt²)M (condition about 1e6): 1.6e-10 measured.
  EXPECT_LT(drift, 1e-9 * work) << "energy drift " << drift << " against the work " << work;
}

// The load ramped in as (t/T)³: a step load would excite every mode of the mesh,
// whose periods no Δt here resolves, and hide the order behind them.
TEST(Newmark, IsOfOrderTwoInTime) {
  const double T = 0.2;  // about a third of the beam's first period
  const auto tip_at_T = [&](int steps) {
    Cantilever beam(T / steps);
    beam.ramp = [T](double t) { return std::pow(t / T, 3); };
    const NewmarkState s = beam.run(steps, Eigen::VectorXd::Zero(2 * beam.mesh.num_vertices()));
    return Eigen::VectorXd(s.u);
  };
  const Eigen::VectorXd reference = tip_at_T(640);
  double last = 0;
  for (int steps : {10, 20, 40}) {
    const double error = (tip_at_T(steps) - reference).norm();
    if (last > 0) {
      const double order = std::log2(last / error);
      EXPECT_GT(order, 1.9) << steps << " steps";
      EXPECT_LT(order, 2.1) << steps << " steps";
    }
    last = error;
  }
}

// No Γ_D, no load: the free body translates at v0, unstrained, its momentum kept.
TEST(Newmark, MovesAFreeBodyRigidlyAtItsInitialVelocity) {
  Cantilever body(0.05, /*clamped=*/false);
  body.b.setZero();
  const int nv = body.mesh.num_vertices();
  Eigen::VectorXd v0(2 * nv);
  v0 << Eigen::VectorXd::Constant(nv, -0.3), Eigen::VectorXd::Constant(nv, 0.2);
  const NewmarkState s = body.run(20, v0);
  EXPECT_NEAR(s.t, 1.0, 1e-15);
  for (int v = 0; v < nv; ++v) {
    EXPECT_NEAR(s.u[v], -0.3, 1e-10) << v;
    EXPECT_NEAR(s.u[nv + v], 0.2, 1e-10) << v;
  }
  const Point velocity = body.newmark->momentum(s.v) / body.newmark->mass();
  // To the round-off of A + (4/Δt²)M, whose condition is about 1e6 here (2e-11 measured).
  EXPECT_NEAR(velocity.x(), -0.3, 1e-9);
  EXPECT_NEAR(velocity.y(), 0.2, 1e-9);
  EXPECT_NEAR(body.newmark->mass(), kRho * 0.1, 1e-12);
  EXPECT_LT(elastic_energy(*body.solver, s.u), 1e-9 * body.newmark->kinetic_energy(s.v));
}

// A Saint-Venant–Kirchhoff beam under the same load: Newton with the inertia's c M in
// its tangent and force converges every step, and for this small load the state stays
// within the linear one's nonlinearity (1e-2 relative at most).
TEST(Newmark, ANonlinearMaterialsStepsTakeTheInertiaInNewtonsMethod) {
  Cantilever linear(0.01, true, 0.5), svk(0.01, true, 0.5);  // tip about 7 mm: 0.7 % of L
  svk.solver->set_material({MaterialModel::saint_venant_kirchhoff, kLame});
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2 * linear.mesh.num_vertices());
  const NewmarkState a = linear.run(30, rest), b = svk.run(30, rest);
  ASSERT_GT(a.u.norm(), 0);
  EXPECT_LT((a.u - b.u).norm(), 1e-2 * a.u.norm());
  EXPECT_GT((a.u - b.u).norm(), 1e-8 * a.u.norm());  // it is the nonlinear model
}

// A time step's feasible-set projection (the relaxation's, coupling/relaxation.hpp) is
// the nearest feasible point in the step operator's norm A_S + c M: no farther from z
// than any other feasible point. A floor 1 mm under the beam; z bends it 3 mm down at
// the tip. With the load A_S z alone (the defect this guards) the "projection" was
// (A_S + c M)⁻¹ A_S z, about 0 where the mass dominates: the whole bend away from z,
// where the nearest point moves only the part below the floor (IQN-ILS's updates on
// paper-7.2-dynamic stalled on it, 12 passes a step instead of 4).
TEST(Newmark, ATimeStepsProjectionIsTheNearestFeasiblePointInItsNorm) {
  for (bool nonlinear : {false, true}) {
    Cantilever beam(1e-4);  // (4/Δt²) M against A_S: the mass's norm dominates
    const int nv = beam.mesh.num_vertices();
    std::vector<int> bottom;  // the bottom's vertices off the clamped side
    for (int v : beam.mesh.vertices_on(beam.mesh.label("bottom")))
      if (beam.mesh.vertices[v].x() > 0) bottom.push_back(v);
    std::vector<Eigen::Triplet<double>> rows;
    for (std::size_t i = 0; i < bottom.size(); ++i) rows.emplace_back(static_cast<int>(i), nv + bottom[i], 1.0);
    ContactConstraint floor{SparseMatrix(static_cast<Eigen::Index>(bottom.size()), 2 * nv),
                            Eigen::VectorXd::Constant(static_cast<Eigen::Index>(bottom.size()), -1e-3), bottom};
    floor.C_S.setFromTriplets(rows.begin(), rows.end());
    beam.solver->set_constraint(floor);
    if (nonlinear) beam.solver->set_material({MaterialModel::saint_venant_kirchhoff, kLame});
    const SparseMatrix K = beam.solver->A_S() + Newmark::operator_factor(beam.dt) * beam.M;
    const auto norm = [&K](const Eigen::VectorXd& x) { return std::sqrt(x.dot(K * x)); };

    Eigen::VectorXd z = Eigen::VectorXd::Zero(2 * nv), clamped = z;
    for (int v = 0; v < nv; ++v) {
      const double x = beam.mesh.vertices[v].x();
      z[nv + v] = -3e-3 * x * x;
      clamped[nv + v] = std::max(z[nv + v], -1e-3);  // feasible: every vertex above the floor
    }
    const Eigen::VectorXd feasible = 0.3 * z;  // a feasible z: the projection keeps it
    EXPECT_EQ((beam.solver->project(feasible) - feasible).norm(), 0.0);
    const Eigen::VectorXd p = beam.solver->project(z);
    EXPECT_GE((floor.C_S * p - floor.c_lb).minCoeff(), -1e-12) << "nonlinear " << nonlinear;
    EXPECT_LE(norm(p - z), norm(clamped - z) * (1 + 1e-9)) << "nonlinear " << nonlinear;
    EXPECT_LT(norm(p - z), 0.5 * norm(z)) << "nonlinear " << nonlinear;
  }
}

}  // namespace
}  // namespace fsi::newmark_test
