// Extremal of the biharmonic energy with the boundary fixed, tensor degree (n, n):
//   Extremal/direct/<n>   one-off solve_extremal: assemble the Gram matrix, factor, solve;
//   Extremal/mould/<n>    with a prebuilt ExtremalSolver: one product with the cached mould;
//   Extremal/factored/<n> with a prebuilt ExtremalSolver: triangular solves with its factor;
//   Extremal/setup/<n>    building the ExtremalSolver (Gram, factorisation, mould).
#include <benchmark/benchmark.h>

#include <cmath>

#include "bezierpde/solvers/extremal.h"

namespace {

bpde::TensorNet boundary_data(int n) {
  bpde::TensorNet net(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      net.set_point(i, j, Eigen::Vector3d(u, v, std::sin(3 * u) * std::cos(2 * v)));
    }
  return net;
}

void BM_ExtremalDirect(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet net = boundary_data(n);
  const bpde::EnergySpec e = bpde::EnergySpec::biharmonic();
  for (auto _ : state) {
    bpde::ExtremalResult r = bpde::solve_extremal(net, e, bpde::FixedSet::Boundary);
    benchmark::DoNotOptimize(r.net.points().data());
  }
}

void BM_ExtremalMould(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet net = boundary_data(n);
  const bpde::ExtremalSolver solver(bpde::EnergySpec::biharmonic(), n, n, bpde::FixedSet::Boundary);
  for (auto _ : state) {
    Eigen::MatrixX3d P = solver.solve(net.points());
    benchmark::DoNotOptimize(P.data());
  }
}

void BM_ExtremalFactored(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet net = boundary_data(n);
  const bpde::ExtremalSolver solver(bpde::EnergySpec::biharmonic(), n, n, bpde::FixedSet::Boundary);
  for (auto _ : state) {
    Eigen::MatrixX3d P = solver.solve_factored(net.points());
    benchmark::DoNotOptimize(P.data());
  }
}

void BM_ExtremalSetup(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    bpde::ExtremalSolver solver(bpde::EnergySpec::biharmonic(), n, n, bpde::FixedSet::Boundary);
    benchmark::DoNotOptimize(solver.mould().data());
  }
}

}  // namespace

BENCHMARK(BM_ExtremalDirect)->Name("Extremal/direct")->DenseRange(4, 20, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExtremalMould)->Name("Extremal/mould")->DenseRange(4, 20, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExtremalFactored)->Name("Extremal/factored")->DenseRange(4, 20, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExtremalSetup)->Name("Extremal/setup")->DenseRange(4, 20, 2)->Unit(benchmark::kMicrosecond);
