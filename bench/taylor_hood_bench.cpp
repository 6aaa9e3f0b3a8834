// Taylor–Hood time steps (fluid.element = "taylor-hood") on DFG 2D-2
// (cases/dfg-2d2.toml, fluid.h_near = 0.01 and 0.005: 4 851 and 13 993 triangles,
// Δt = 0.005, BDF2, 100 steps from rest): Newton with a fresh Jacobian every step
// against the chord method (TaylorHoodOptions::reuse_factors, the default), with the
// time per step, the factorisations and the chord steps, so that the reuse's gain can
// be set against the factorisation's share. docs/performance.md gives the numbers.
//   build/bench/taylor_hood_bench
#include <benchmark/benchmark.h>

#include <map>

#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/taylor_hood_setup.hpp"

namespace fsi {
namespace {

constexpr int kSteps = 100;

const Case& dfg(const std::string& h_near) {
  static std::map<std::string, Case> cases;
  if (!cases.count(h_near))
    cases[h_near] = load_case(std::string(FSICONTACT_SOURCE_DIR) + "/cases/dfg-2d2.toml",
                              {"fluid.element=taylor-hood", "fluid.h_near=" + h_near, "time.dt=0.005"});
  return cases[h_near];
}

void BM_TaylorHoodSteps(benchmark::State& state, const std::string& h_near, bool reuse) {
  const Case& c = dfg(h_near);
  TaylorHoodSetup s = make_taylor_hood(c, make_fluid_mesh(c));
  TaylorHoodOptions options;
  options.tol = c.fluid->newton_tol;
  options.max_steps = c.fluid->newton_max_steps;
  options.reuse_factors = reuse;
  double seconds = 0;
  int factorizations = 0, chord = 0;
  for (auto _ : state) {
    TaylorHoodFlow flow(*s.system, options);
    flow.start(c.fluid->rho, TimeScheme::bdf2, c.time->dt, Eigen::VectorXd::Zero(s.system->dofs()));
    for (int k = 0; k < kSteps; ++k) flow.step([&](double t) { set_taylor_hood_data(s, c, t); });
    const TaylorHoodTiming& t = flow.timing();
    seconds = t.assembly + t.factorization + t.solve;
    factorizations = flow.factorizations(), chord = flow.chord_steps();
  }
  state.counters["triangles"] = s.mesh->num_triangles();
  state.counters["s_per_step"] = seconds / kSteps;
  state.counters["factorizations"] = factorizations;
  state.counters["chord_steps"] = chord;
}

[[maybe_unused]] const bool registered = [] {
  for (const char* h : {"0.01", "0.005"})
    for (bool reuse : {false, true})
      benchmark::RegisterBenchmark((std::string("taylor_hood_steps/h_near:") + h + (reuse ? "/chord" : "/newton")).c_str(),
                                   BM_TaylorHoodSteps, std::string(h), reuse)
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
  return true;
}();

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
