// What SPEC §10's expressions cost where the fluid evaluates them: its body force f_F
// at every point of the degree-6 rule on every triangle (StokesAssembler::
// set_body_force, once per run: the load does not change between fixed-point passes),
// on the paper's §7.2 box at hF = 0.01, for a number (the constant lambda of before)
// and for expressions of one, two and more operations per component; and one whole
// fluid solve from scratch with each (set-up, assembly, factorisation, solve), whose
// difference is the expression's share. ns_per_point is the time per quadrature point
// (both components): of the field alone (evaluate/) and of the element loads with it
// (body_force/); docs/performance.md gives the numbers.
//   build-expr/bench/expression_bench
//   build-expr/bench/expression_bench --benchmark_filter=body_force
#include <benchmark/benchmark.h>

#include <memory>

#include "fem/p1.hpp"
#include "fem/quadrature.hpp"
#include "io/case.hpp"
#include "run/case_fields.hpp"
#include "run/fluid_setup.hpp"
#include "run/structure_setup.hpp"

namespace fsi {
namespace {

// fluid.f of each variant, as --set gives it.
struct Load {
  const char* name;
  const char* setting;
};
const Load kLoads[] = {
    {"number", "fluid.f=[0.0, -981.0]"},
    {"one_component", "fluid.f=[0, \"-981*(1 + x/0.41)\"]"},
    {"two_components", "fluid.f=[\"0.1*y\", \"-981*(1 + x/0.41)\"]"},
    {"transcendental", "fluid.f=[0, \"-981*(1 + 0.5*sin(pi*x/0.41)*exp(-y^2))\"]"},
};

// The §7.2 box at hF = 0.01, its mesh and χ of the structure at rest, built once.
struct Box {
  Case c = load_case("", {"fluid.h=0.01"});
  FluidSetup fluid = make_fluid(c, make_fluid_mesh(c), c.coupling.eps);
  Eigen::VectorXd chi = (*fluid.chi)(make_structure_mesh(c));
};

Box& box() {
  static Box b;
  return b;
}

VectorField body_force(const Load& load) { return fluid_body_force(*load_case("", {load.setting}).fluid); }

// The points set_body_force evaluates f_F at: every point of the degree-6 rule on every triangle.
const std::vector<Point>& quadrature_points() {
  static const std::vector<Point> points = [] {
    std::vector<Point> x;
    const TriangleRule rule = triangle_rule(6);
    const Mesh& mesh = *box().fluid.mesh;
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      const P1Triangle T(mesh, t);
      for (const Eigen::Vector3d& l : rule.lambda) x.push_back(T.point(l));
    }
    return x;
  }();
  return points;
}

// The field alone at those points: what one evaluation costs, the assembly around it aside.
void BM_Evaluate(benchmark::State& state, const Load& load) {
  const VectorField f = body_force(load);
  const std::vector<Point>& points = quadrature_points();
  for (auto _ : state) {
    Point sum = Point::Zero();
    for (const Point& x : points) sum += f(x);
    benchmark::DoNotOptimize(sum.data());
  }
  state.counters["ns_per_point"] = benchmark::Counter(static_cast<double>(points.size()) * 1e-9,
                                                      benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
}

void BM_BodyForce(benchmark::State& state, const Load& load) {
  Box& b = box();
  const VectorField f = body_force(load);
  const FluidParams& p = *b.c.fluid;
  StokesAssembler assembler(*b.fluid.mesh, p.mu, f, box_boundary_conditions(*b.fluid.mesh, p));
  for (auto _ : state) assembler.set_body_force(f);
  const double points = static_cast<double>(b.fluid.mesh->num_triangles() * triangle_rule(6).w.size());
  state.counters["points"] = points;
  state.counters["ns_per_point"] =
      benchmark::Counter(points * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// One fluid solve from nothing but the mesh: the solver's set-up (the body force's
// loads among it), the assembly, the whole factorisation and the solve, for χ at rest.
void BM_FluidSolve(benchmark::State& state, const Load& load) {
  Box& b = box();
  const VectorField f = body_force(load);
  const FluidParams& p = *b.c.fluid;
  for (auto _ : state) {
    PenalisedStokes stokes(*b.fluid.mesh, p.mu, b.c.coupling.eps, f, box_boundary_conditions(*b.fluid.mesh, p));
    stokes.set_chi(b.chi);
    benchmark::DoNotOptimize(stokes.solve().p.data());
  }
  state.counters["triangles"] = b.fluid.mesh->num_triangles();
}

void register_all() {
  for (const Load& load : kLoads) {
    benchmark::RegisterBenchmark((std::string("evaluate/") + load.name + "/hF:0.01").c_str(), BM_Evaluate, load)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("body_force/") + load.name + "/hF:0.01").c_str(), BM_BodyForce, load)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("fluid_solve/") + load.name + "/hF:0.01").c_str(), BM_FluidSolve, load)
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
