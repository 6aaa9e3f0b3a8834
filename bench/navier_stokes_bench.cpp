// Steady Navier–Stokes (SPEC §10) on the DFG 2D-1 channel (cases/dfg-2d1.toml) at
// fluid.h = 0.01 and 0.005 (about 21 000 and 83 000 triangles): for each sparse
// solver that factors unsymmetric matrices, a whole Newton solve from rest (the
// symbolic analysis once, one numeric factorisation per step, the assemblies, the
// bubbles) and one numeric factorisation of the Jacobian at the solution alone, so
// that the time per Newton step can be set against the factorisation's.
// docs/performance.md gives the commands and the numbers.
//   build/bench/navier_stokes_bench --benchmark_filter='newton_solve/.*'
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "io/case.hpp"
#include "run/fluid_setup.hpp"

namespace fsi {
namespace {

const std::vector<std::string> kSizes = {"0.01", "0.005"};
const std::vector<std::string> kSolvers = {"mumps-lu", "umfpack", "umfpack-metis"};

struct Channel {
  Case c;
  std::unique_ptr<Mesh> mesh;
};

Channel& channel(const std::string& h) {
  static std::map<std::string, Channel> channels;
  Channel& ch = channels[h];
  if (!ch.mesh) {
    ch.c = load_case(std::string(FSICONTACT_SOURCE_DIR) + "/cases/dfg-2d1.toml", {"fluid.h=" + h});
    ch.mesh = std::make_unique<Mesh>(make_fluid_mesh(ch.c));
  }
  return ch;
}

std::unique_ptr<PenalisedStokes> navier_stokes(const Channel& ch, const std::string& solver) {
  const FluidParams& f = *ch.c.fluid;
  auto s = std::make_unique<PenalisedStokes>(*ch.mesh, f.mu, 1.0, [](const Point&) { return Point(0, 0); },
                                             box_boundary_conditions(*ch.mesh, f), solver, FluidFactorization::whole);
  set_fluid_model(*s, f);
  s->set_chi(Eigen::VectorXd::Zero(ch.mesh->num_triangles()));
  return s;
}

void BM_NewtonSolve(benchmark::State& state, const std::string& solver, const std::string& h) {
  const Channel& ch = channel(h);
  int steps = 0;
  double factorization = 0, assembly = 0, total = 0;
  for (auto _ : state) {
    const auto s = navier_stokes(ch, solver);
    s->solve();
    steps = s->newton()->steps;
    factorization = s->timing().factorization, assembly = s->timing().assembly;
    total = s->timing().factorization + s->timing().assembly + s->timing().solve;
  }
  state.counters["triangles"] = ch.mesh->num_triangles();
  state.counters["newton_steps"] = steps;
  state.counters["s_per_step"] = total / steps;
  state.counters["factorization_s"] = factorization;
  state.counters["assembly_s"] = assembly;
}

// One numeric factorisation of the Jacobian at the solution (its analysis outside).
void BM_JacobianFactorize(benchmark::State& state, const std::string& solver_name, const std::string& h) {
  const Channel& ch = channel(h);
  const auto s = navier_stokes(ch, "mumps-lu");
  s->solve();
  s->assemble_full();  // the Jacobian at the solution
  auto solver = make_sparse_solver(solver_name);
  solver->analyze(s->matrix());
  for (auto _ : state) solver->factorize(s->matrix());
  state.counters["triangles"] = ch.mesh->num_triangles();
  const FactorStatistics f = solver->statistics();
  if (f.entries > 0) state.counters["factor_entries"] = f.entries;
}

void register_all() {
  for (const std::string& h : kSizes)
    for (const std::string& solver : kSolvers) {
      const std::string tail = solver + "/h:" + h;
      benchmark::RegisterBenchmark(("newton_solve/" + tail).c_str(), BM_NewtonSolve, solver, h)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(2);
      benchmark::RegisterBenchmark(("jacobian_factorize/" + tail).c_str(), BM_JacobianFactorize, solver, h)
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
