// The structure's phases (SPEC §2) on the paper's §7.2 beam (gravity load only, which
// already presses it on the obstacle), against the mesh size hS:
//   assembly of A_S and of C_S, c_lb; the solver set-up (sparse Cholesky of A_S and
//   the Schur complement S = C A⁻¹Cᵀ of the active-set solver); one contact QP by the
//   active-set solver, cold and warm-started from its own solution, and by IPOPT.
//   build/bench/structure_bench [--benchmark_filter=Qp]
// docs/performance.md gives the numbers and what they mean for a coupled run.
#include <benchmark/benchmark.h>

#include "io/case.hpp"
#include "run/structure_setup.hpp"
#include "solid/contact.hpp"
#include "solid/elasticity.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi {
namespace {

// hS = 0.015 / 2^k, k = range(0): 0.015, 0.0075, 0.00375, 0.001875.
Case beam_case(const benchmark::State& state, const std::string& solver = "active-set") {
  Case c = load_case("", {"structure.h=" + std::to_string(0.015 / (1 << state.range(0))),
                          "contact.solver=\"" + solver + "\""});
  c.fluid.reset();
  return c;
}

void mesh_counters(benchmark::State& state, const Mesh& mesh, Eigen::Index contact_rows = -1) {
  state.counters["triangles"] = mesh.num_triangles();
  state.counters["dofs"] = 2 * mesh.num_vertices();
  if (contact_rows >= 0) state.counters["contact_rows"] = static_cast<double>(contact_rows);
}

void BM_AssembleA_S(benchmark::State& state) {
  const Case c = beam_case(state);
  const Mesh mesh = make_structure_mesh(c);
  const Lame lame = Lame::from_young_poisson(c.structure.E, c.structure.nu);
  for (auto _ : state) benchmark::DoNotOptimize(assemble_elasticity(mesh, lame));
  mesh_counters(state, mesh);
}

void BM_AssembleC_S(benchmark::State& state) {
  const Case c = beam_case(state);
  const Mesh mesh = make_structure_mesh(c);
  const DiskFoundation psi(c.obstacle.x0, c.obstacle.y0, c.obstacle.r);
  Eigen::Index rows = 0;
  for (auto _ : state) {
    const ContactConstraint cc = assemble_contact(mesh, mesh.label("Gamma_C"), psi);
    rows = cc.C_S.rows();
    benchmark::DoNotOptimize(cc.c_lb.data());
  }
  mesh_counters(state, mesh, rows);
}

// A_S, C_S, the elimination of Γ_D and the QP solver's set_operator (Cholesky, S).
void BM_SolverSetup(benchmark::State& state) {
  const Case c = beam_case(state);
  const Mesh mesh = make_structure_mesh(c);
  for (auto _ : state) benchmark::DoNotOptimize(make_structure(c, mesh, nullptr).solver.get());
  mesh_counters(state, mesh);
}

// One contact QP; range(1) = 1: warm-started from the solution itself (what the
// fixed-point loop sees near convergence: the active set no longer changes).
void BM_Qp(benchmark::State& state, const std::string& solver) {
  const Case c = beam_case(state, solver);
  const Mesh mesh = make_structure_mesh(c);
  StructureSetup s = make_structure(c, mesh, nullptr);
  const ContactSolution first = s.solver->solve(s.b_applied);
  const bool warm = state.range(1) == 1;
  int iterations = 0;
  for (auto _ : state) {
    const ContactSolution next = s.solver->solve(s.b_applied, warm ? &first : nullptr);
    iterations = next.qp.iterations;
    benchmark::DoNotOptimize(next.u.data());
  }
  mesh_counters(state, mesh, s.solver->contact().C_S.rows());
  state.counters["qp_iterations"] = iterations;
  state.counters["active"] = first.qp.active_count();
}
void BM_QpActiveSet(benchmark::State& state) { BM_Qp(state, "active-set"); }
void BM_QpIpopt(benchmark::State& state) { BM_Qp(state, "ipopt"); }

// A coupled pass's structure solve (SPEC §11: a hyperelastic pass may cost at most 3×
// a linear one): the load alternates between b and 1.02 b, each solve warm-started
// from the other's solution, as consecutive fixed-point passes are. range(1): the
// model, 0 linear, 1 Saint-Venant–Kirchhoff, 2 neo-Hookean; range(2): 0 P1, 1 P2.
void BM_StructurePass(benchmark::State& state) {
  Case c = beam_case(state);
  const char* models[] = {"linear", "saint-venant-kirchhoff", "neo-hookean"};
  c.structure.model = models[state.range(1)];
  c.structure.element = state.range(2) ? "P2" : "P1";
  const Mesh mesh = make_structure_mesh(c);
  StructureSetup s = make_structure(c, mesh, nullptr);
  const Eigen::VectorXd loads[2] = {s.b_applied, 1.02 * s.b_applied};
  ContactSolution last[2] = {s.solver->solve(loads[0]), s.solver->solve(loads[1])};
  int k = 0, steps = 0;
  for (auto _ : state) {
    last[k] = s.solver->solve(loads[k], &last[1 - k]);
    steps = last[k].newton.steps;
    benchmark::DoNotOptimize(last[k].u.data());
    k = 1 - k;
  }
  mesh_counters(state, s.mesh(), s.solver->contact().C_S.rows());  // P2: its nodal mesh's
  state.counters["newton_steps"] = steps;
}

BENCHMARK(BM_StructurePass)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}, {0, 1}})
    ->ArgNames({"hS_level", "model", "P2"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AssembleA_S)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AssembleC_S)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolverSetup)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QpActiveSet)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->ArgNames({"hS_level", "warm"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QpIpopt)->ArgsProduct({{0, 1, 2, 3}, {0}})->ArgNames({"hS_level", "warm"})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
