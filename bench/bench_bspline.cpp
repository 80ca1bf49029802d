// B-spline routes (Sun–Zhu, B-spline Euler–Lagrange). A bicubic (biquintic for the PDE) net with s x s uniform spans (s
// = last token, the "degree" slot of the route holds the span count) and a wavy boundary:
//   BSplineExtremal/direct/<s>   solve_bspline_extremal: assemble the sparse Gram, factor, solve;
//   BSplineExtremal/reuse/<s>    BSplineExtremalSolver built once, solve per iteration;
//   BSplinePde/lu/<s>            solve_bspline_pde (span-wise Bernstein equations, rank-revealing),
//                                biharmonic operator, on the same net (generic data: the rank and
//                                consistency decision are what is timed).
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench_data.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"

namespace {

using bpde_bench::wavy_bspline;

void Direct(benchmark::State& state) {
  const auto net = wavy_bspline(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(bpde::solve_bspline_extremal(net, bpde::EnergySpec::biharmonic()).energy);
}

void Reuse(benchmark::State& state) {
  const auto net = wavy_bspline(static_cast<int>(state.range(0)));
  const bpde::BSplineExtremalSolver solver(net.p(), net.q(), net.knots_u(), net.knots_v(),
                                           bpde::EnergySpec::biharmonic(), net.fixed_indices(bpde::FixedSet::Boundary));
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(net).energy);
}

void Pde(benchmark::State& state) {
  const auto net = wavy_bspline(static_cast<int>(state.range(0)), 5);
  for (auto _ : state) benchmark::DoNotOptimize(bpde::solve_bspline_pde(net, bpde::EnergySpec::biharmonic()).rank);
}

}  // namespace

BENCHMARK(Direct)->Name("BSplineExtremal/direct")->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(Reuse)->Name("BSplineExtremal/reuse")->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(Pde)->Name("BSplinePde/lu")->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
