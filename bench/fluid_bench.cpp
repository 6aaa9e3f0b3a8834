// The fluid solve (SPEC §3) on the paper's §7.2 box at hF = 0.02 … 0.0025, for every
// sparse direct solver make_sparse_solver knows: full assembly of the condensed
// Stokes system, numeric factorisation (symbolic analysis done once, outside the
// timing, and reused), one solve, and one PenalisedStokes::solve() after a χ change
// (incremental assembly + factorisation + solve + bubbles + residual check); and the
// substructured solve: the far field's set-up, the near solve per χ, the expansion.
// χ alternates between the undeformed structure and the structure displaced by
// 0.1·u_g (u_g: its contact solution under gravity), the first step of the paper's
// iteration with ω = 0.1. docs/performance.md gives the commands and the numbers.
//   build/bench/fluid_bench --benchmark_filter='factorize/.*/hF:0.01$'
//   build/bench/fluid_bench --benchmark_filter='(far_setup|near_solve).*'  # substructured
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "common/timer.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

const std::vector<std::string> kSizes = {"0.02", "0.01", "0.005", "0.0025"};

struct Box {
  Case c;
  FluidSetup fluid;  // its stokes uses the default solver; χ = chi_rest, assembled
  Eigen::VectorXd chi_rest, chi_moved;
  int chi_changes = 0;      // triangles where the two differ
  Eigen::VectorXd umfpack;  // UMFPACK's solution for chi_rest, on first use
};

// One box per hF, built on first use (meshing hF = 0.0025 takes seconds).
Box& box(const std::string& hF) {
  static std::map<std::string, std::unique_ptr<Box>> boxes;
  auto& slot = boxes[hF];
  if (!slot) {
    slot = std::make_unique<Box>();
    Box& b = *slot;
    b.c = load_case("", {"fluid.h=" + hF});
    b.fluid = make_fluid(b.c, make_fluid_mesh(b.c), b.c.coupling.eps);
    StructureSetup s = make_structure(b.c, make_structure_mesh(b.c), nullptr);
    const Eigen::VectorXd u = 0.1 * s.solver->solve(s.b_applied).u;
    const int nv = s.mesh().num_vertices();
    b.chi_rest = (*b.fluid.chi)(s.mesh());
    b.chi_moved = (*b.fluid.chi)(displaced(s.mesh(), u.head(nv), u.tail(nv)));
    b.chi_changes = static_cast<int>((b.chi_rest.array() != b.chi_moved.array()).count());
    b.fluid.stokes->set_chi(b.chi_rest);
    b.fluid.stokes->assemble_full();
  }
  return *slot;
}

std::unique_ptr<PenalisedStokes> stokes_with(const Box& b, const std::string& solver) {
  const FluidParams& f = *b.c.fluid;
  const Point f_F = f.f;
  return std::make_unique<PenalisedStokes>(
      *b.fluid.mesh, f.mu, b.c.coupling.eps, [f_F](const Point&) { return f_F; },
      box_boundary_conditions(*b.fluid.mesh, f), solver);
}

const Eigen::VectorXd& umfpack_solution(Box& b) {
  if (b.umfpack.size() == 0) {
    auto solver = make_sparse_solver("umfpack");
    solver->analyze(b.fluid.stokes->matrix());
    solver->factorize(b.fluid.stokes->matrix());
    b.umfpack = solver->solve(b.fluid.stokes->rhs());
  }
  return b.umfpack;
}

void size_counters(benchmark::State& state, const Box& b) {
  state.counters["unknowns"] = b.fluid.stokes->unknowns();
  state.counters["nonzeros"] = static_cast<double>(b.fluid.stokes->nonzeros());
}

void BM_Assembly(benchmark::State& state, const std::string& hF) {
  Box& b = box(hF);
  for (auto _ : state) {
    b.fluid.stokes->assemble_full();
    benchmark::DoNotOptimize(b.fluid.stokes->matrix().valuePtr());
  }
  size_counters(state, b);
}

// The analysis outside the loop (its time as a counter), reused by every
// factorisation; the library's own count of the factors' entries and flops.
void BM_Factorize(benchmark::State& state, const std::string& solver_name, const std::string& hF) {
  Box& b = box(hF);
  const auto& K = b.fluid.stokes->matrix();
  auto solver = make_sparse_solver(solver_name);
  const Stopwatch clock;
  solver->analyze(K);
  state.counters["analysis_s"] = clock.elapsed();
  for (auto _ : state) solver->factorize(K);
  state.counters["analyses"] = solver->analyses();
  const FactorStatistics statistics = solver->statistics();
  if (statistics.entries >= 0) state.counters["factor_entries"] = statistics.entries;
  if (statistics.flops >= 0) state.counters["factor_flops"] = statistics.flops;
  size_counters(state, b);
}

void BM_Solve(benchmark::State& state, const std::string& solver_name, const std::string& hF) {
  Box& b = box(hF);
  const auto& K = b.fluid.stokes->matrix();
  auto solver = make_sparse_solver(solver_name);
  solver->analyze(K);
  solver->factorize(K);
  Eigen::VectorXd x;
  for (auto _ : state) {
    x = solver->solve(b.fluid.stokes->rhs());
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["relative_residual"] =
      (K * x - b.fluid.stokes->rhs()).norm() / b.fluid.stokes->rhs().norm();
  state.counters["difference_to_umfpack"] =
      (x - umfpack_solution(b)).norm() / umfpack_solution(b).norm();
  size_counters(state, b);
}

void BM_StokesSolve(benchmark::State& state, const std::string& solver_name,
                    const std::string& hF) {
  Box& b = box(hF);
  auto stokes = stokes_with(b, solver_name);
  stokes->set_chi(b.chi_rest);
  stokes->solve();  // the analysis and first full assembly, outside the loop
  bool moved = false;
  for (auto _ : state) {
    moved = !moved;
    stokes->set_chi(moved ? b.chi_moved : b.chi_rest);
    benchmark::DoNotOptimize(stokes->solve().p.data());
  }
  state.counters["chi_changes"] = b.chi_changes;
  size_counters(state, b);
}

// The substructured solve (fluid.factorization = "schur", the default): the far
// field's set-up when the near region is chosen (METIS order of the vertex graph,
// far-field assembly, MUMPS partial factorisation with S, condensation, the near
// pattern's analysis) together with the first near solve; then, per χ change, the
// near solve alone (what a coupling step pays), or with the expansion to the far
// field (solve() sampled everywhere, what the outputs need).
std::unique_ptr<PenalisedStokes> substructured(const Box& b) {
  auto stokes = stokes_with(b, kDefaultSparseSolver);
  stokes->set_factorization(FluidFactorization::schur);
  return stokes;
}

// The triangles of χ's support: where the structure samples the fields.
std::vector<int> support(const Eigen::VectorXd& chi) {
  std::vector<int> triangles;
  for (Eigen::Index t = 0; t < chi.size(); ++t)
    if (chi[t] != 0) triangles.push_back(static_cast<int>(t));
  return triangles;
}

void region_counters(benchmark::State& state, const PenalisedStokes& stokes) {
  if (const RegionSchurSolver* r = stokes.region()) {
    state.counters["near_unknowns"] = r->near_unknowns();
    state.counters["interface_unknowns"] = r->interface_unknowns();
    state.counters["far_factor_MB"] = r->far_factor_mb();
  }
  state.counters["regions"] = stokes.timing().regions;
}

void BM_FarSetup(benchmark::State& state, const std::string& hF) {
  Box& b = box(hF);
  std::unique_ptr<PenalisedStokes> stokes;
  const std::vector<int> sampled = support(b.chi_rest);
  for (auto _ : state) {
    state.PauseTiming();
    stokes = substructured(b);
    stokes->set_chi(b.chi_rest);
    state.ResumeTiming();
    benchmark::DoNotOptimize(stokes->solve(&sampled).p.data());
  }
  region_counters(state, *stokes);
  size_counters(state, b);
}

void BM_NearSolve(benchmark::State& state, const std::string& hF, bool expand) {
  Box& b = box(hF);
  auto stokes = substructured(b);
  const std::vector<int> at_rest = support(b.chi_rest), moved_to = support(b.chi_moved);
  stokes->set_chi(b.chi_rest);
  stokes->solve(&at_rest);  // the far field's set-up, outside the loop
  bool moved = false;
  for (auto _ : state) {
    moved = !moved;
    stokes->set_chi(moved ? b.chi_moved : b.chi_rest);
    benchmark::DoNotOptimize(stokes->solve(expand ? nullptr : moved ? &moved_to : &at_rest).p.data());
  }
  region_counters(state, *stokes);
  state.counters["chi_changes"] = b.chi_changes;
  size_counters(state, b);
}

void register_all() {
  for (const std::string& hF : kSizes) {
    benchmark::RegisterBenchmark(("assembly/hF:" + hF).c_str(), BM_Assembly, hF)
        ->Unit(benchmark::kMillisecond);
    for (const std::string& solver : sparse_solver_names()) {
      const std::string tail = solver + "/hF:" + hF;
      benchmark::RegisterBenchmark(("factorize/" + tail).c_str(), BM_Factorize, solver, hF)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("solve/" + tail).c_str(), BM_Solve, solver, hF)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("stokes_solve/" + tail).c_str(), BM_StokesSolve, solver, hF)
          ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark(("far_setup/hF:" + hF).c_str(), BM_FarSetup, hF)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("near_solve/hF:" + hF).c_str(), BM_NearSolve, hF, false)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("near_solve_expanded/hF:" + hF).c_str(), BM_NearSolve, hF, true)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace
}  // namespace fsi

int main(int argc, char** argv) {
  fsi::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
