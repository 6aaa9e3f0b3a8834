// The transfer phases of one fixed-point iteration (SPEC §4–§5) on the paper's §7.2
// case (hF = 0.01, hS = 0.015 / 2^k): χ of the deformed structure on the fluid mesh
// (both rules), v_h and p_h at the deformed vertices (point location, bubble
// included), the force of eq. (33), and ‖v_h‖ over the deformed structure. The
// structure state is the contact solution under gravity, the fluid the Stokes
// solution with its χ: the geometry of a real iteration.
//   build/bench/coupling_bench
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "coupling/force_transfer.hpp"
#include "io/case.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

struct Scene {
  Case c;
  StructureSetup structure;
  FluidSetup fluid;
  Eigen::VectorXd u;
  Mesh deformed;
};

// One scene per structure level, built on first use (the fluid solve takes ~0.2 s).
Scene& scene(int hS_level) {
  static std::map<int, std::unique_ptr<Scene>> scenes;
  auto& slot = scenes[hS_level];
  if (!slot) {
    slot = std::make_unique<Scene>();
    Scene& s = *slot;
    s.c = load_case("", {"structure.h=" + std::to_string(0.015 / (1 << hS_level))});
    s.structure = make_structure(s.c, make_structure_mesh(s.c), nullptr);
    s.fluid = make_fluid(s.c, make_fluid_mesh(s.c), s.c.coupling.eps);
    s.u = s.structure.solver->solve(s.structure.b_applied).u;
    const int nv = s.structure.mesh().num_vertices();
    s.deformed = displaced(s.structure.mesh(), s.u.head(nv), s.u.tail(nv));
    s.fluid.stokes->set_chi((*s.fluid.chi)(s.deformed));
    s.fluid.stokes->solve();
  }
  return *slot;
}

void counters(benchmark::State& state, const Scene& s) {
  state.counters["structure_vertices"] = s.structure.mesh().num_vertices();
  state.counters["fluid_triangles"] = s.fluid.mesh->num_triangles();
}

void BM_Chi(benchmark::State& state, const std::string& rule) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const ChiComputer chi(*s.fluid.mesh, *s.fluid.locator, rule);
  for (auto _ : state) benchmark::DoNotOptimize(chi(s.deformed).data());
  counters(state, s);
}
void BM_ChiBarycentre(benchmark::State& state) { BM_Chi(state, "barycentre"); }
void BM_ChiAreaFraction(benchmark::State& state) { BM_Chi(state, "area-fraction"); }

void BM_SampleAtDeformedVertices(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const FluidField field(*s.fluid.locator, s.fluid.stokes->solution());
  for (auto _ : state)
    benchmark::DoNotOptimize(sample_at_deformed_vertices(field, s.structure.mesh(), s.u).v.data());
  counters(state, s);
}

void BM_FluidForce(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const FluidField field(*s.fluid.locator, s.fluid.stokes->solution());
  const SampledFluid sampled = sample_at_deformed_vertices(field, s.structure.mesh(), s.u);
  const Point f_F = s.c.fluid->f;
  const FluidForce force(s.structure.mesh(), s.c.fluid->mu, s.c.coupling.eps,
                         [f_F](const Point&) { return f_F; });
  for (auto _ : state) benchmark::DoNotOptimize(force(sampled, s.u).data());
  counters(state, s);
}

void BM_VelocityL2OverStructure(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const FluidField field(*s.fluid.locator, s.fluid.stokes->solution());
  for (auto _ : state) benchmark::DoNotOptimize(velocity_l2_over(field, s.deformed));
  counters(state, s);
}

BENCHMARK(BM_ChiBarycentre)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChiAreaFraction)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SampleAtDeformedVertices)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FluidForce)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_VelocityL2OverStructure)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fsi

BENCHMARK_MAIN();
