// B-spline routes (Sun–Zhu, B-spline Euler–Lagrange). A bicubic (biquintic for the PDE) net with s x s uniform spans (s
// = last token, the "degree" slot of the route holds the span count) and a wavy boundary:
//   BSplineExtremal/direct/<s>   solve_bspline_extremal: assemble the sparse Gram, factor, solve;
//   BSplineExtremal/reuse/<s>    BSplineExtremalSolver built once, solve per iteration;
//   BSplinePde/lu/<s>            solve_bspline_pde (span-wise Bernstein equations, rank-revealing),
//                                biharmonic operator, on the same net (generic data: the rank and
//                                consistency decision are what is timed).
#include <benchmark/benchmark.h>

#include <cmath>

#include "solvers/bspline/bspline_extremal.h"
#include "solvers/bspline/bspline_pde.h"

namespace {

bpde::BSplineNet wavy(int spans, int p = 3) {
  std::vector<double> K(p, 0.0);
  for (int s = 0; s <= spans; ++s) K.push_back(static_cast<double>(s) / spans);
  K.insert(K.end(), p, 1.0);
  const int n = static_cast<int>(K.size()) - p - 1;
  Eigen::MatrixX3d P(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      P.row(i * n + j) << static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1),
          0.2 * std::sin(3.0 * i / n) * std::cos(2.0 * j / n);
  return bpde::BSplineNet(p, p, K, K, P);
}

void Direct(benchmark::State& state) {
  const auto net = wavy(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(bpde::solve_bspline_extremal(net, bpde::EnergySpec::biharmonic()).energy);
}

void Reuse(benchmark::State& state) {
  const auto net = wavy(static_cast<int>(state.range(0)));
  const bpde::BSplineExtremalSolver solver(net.p(), net.q(), net.knots_u(), net.knots_v(),
                                           bpde::EnergySpec::biharmonic(), net.fixed_indices(bpde::FixedSet::Boundary));
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(net).energy);
}

void Pde(benchmark::State& state) {
  const auto net = wavy(static_cast<int>(state.range(0)), 5);
  for (auto _ : state) benchmark::DoNotOptimize(bpde::solve_bspline_pde(net, bpde::EnergySpec::biharmonic()).rank);
}

}  // namespace

BENCHMARK(Direct)->Name("BSplineExtremal/direct")->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(Reuse)->Name("BSplineExtremal/reuse")->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(Pde)->Name("BSplinePde/lu")->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
