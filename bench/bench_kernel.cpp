// The hand-written kernel core/row_major_product against Eigen's product on the same row-major
// operands (docs/performance_measurements.md "Kernels"), compiled with the same flags:
//   Kernel/grid-{row-major,eigen}/<n>    one coordinate of a 51 x 51 grid evaluation of a degree-(n, n)
//                                        patch: T = P BvT ((n+1) x 51), X = Bu T (51 x 51);
//   Kernel/mould-{row-major,eigen}/<n>   the mould product of the tensor pde lu route, x, y, z at once:
//                                        3 x 4n times 4n x (n-1)^2 (solvers/pde/pde_lu.cpp);
//   Kernel/rows-{row-major,eigen}/<r>    r = 1, 2, 3, 4 rows times the n = 20 mould (80 x 361);
//   Kernel/fma-peak                      independent multiply-adds: the core's peak FLOP rate.
#include <benchmark/benchmark.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <random>

#include "bezierpde/core/row_major_product.h"

namespace {

using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

RowMat random(int r, int c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  RowMat M(r, c);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) M(i, j) = U(rng);
  return M;
}

// C = A B by the kernel or by Eigen.
void product(bool eigen, const RowMat& A, const RowMat& B, RowMat& C) {
  if (eigen) {
    C.noalias() = A * B;
  } else {
    bpde::row_major_product(A.data(), static_cast<int>(A.rows()), static_cast<int>(A.cols()),
                            static_cast<int>(A.cols()), B.data(), static_cast<int>(B.cols()),
                            static_cast<int>(B.cols()), C.data(), static_cast<int>(C.cols()));
  }
}

void Grid(benchmark::State& state, bool eigen) {
  const int n = static_cast<int>(state.range(0));
  const RowMat P = random(n + 1, n + 1, 1), BvT = random(n + 1, 51, 2), Bu = random(51, n + 1, 3);
  RowMat T(n + 1, 51), X(51, 51);
  for (auto _ : state) {
    product(eigen, P, BvT, T);
    product(eigen, Bu, T, X);
    benchmark::DoNotOptimize(X.data());
  }
  state.counters["flops"] =
      benchmark::Counter(2.0 * (n + 1) * 51 * (n + 1 + 51), benchmark::Counter::kIsIterationInvariantRate);
}

void Mould(benchmark::State& state, bool eigen) {
  const int n = static_cast<int>(state.range(0));
  const RowMat XB = random(3, 4 * n, 4), S = random(4 * n, (n - 1) * (n - 1), 5);
  RowMat XF(3, (n - 1) * (n - 1));
  for (auto _ : state) {
    product(eigen, XB, S, XF);
    benchmark::DoNotOptimize(XF.data());
  }
  state.counters["flops"] =
      benchmark::Counter(2.0 * 3 * 4 * n * (n - 1) * (n - 1), benchmark::Counter::kIsIterationInvariantRate);
}

void Rows(benchmark::State& state, bool eigen) {
  const int r = static_cast<int>(state.range(0));
  const RowMat A = random(r, 80, 6), S = random(80, 361, 7);
  RowMat C(r, 361);
  for (auto _ : state) {
    product(eigen, A, S, C);
    benchmark::DoNotOptimize(C.data());
  }
}

// The machine's multiply-add peak of one core: 64 independent accumulators (acc = acc * a + b,
// vectorised and contracted to FMA by the compiler at the build's flags), 2 flops each per step.
// The yardstick of the kernels' FLOP rates (docs/performance_measurements.md "Kernels").
void FmaPeak(benchmark::State& state) {
  constexpr int kAcc = 64, kSteps = 4096;
  alignas(64) double acc[kAcc];
  for (int i = 0; i < kAcc; ++i) acc[i] = 1.0 + 1e-3 * i;
  double a = 0.999999, b = 1e-7;
  benchmark::DoNotOptimize(a);
  benchmark::DoNotOptimize(b);
  for (auto _ : state) {
    for (int s = 0; s < kSteps; ++s)
      for (int i = 0; i < kAcc; ++i) acc[i] = acc[i] * a + b;
    benchmark::DoNotOptimize(acc);
  }
  state.counters["flops"] = benchmark::Counter(2.0 * kAcc * kSteps, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(FmaPeak)->Name("Kernel/fma-peak");
BENCHMARK_CAPTURE(Grid, rm, false)->Name("Kernel/grid-row-major")->Arg(5)->Arg(10)->Arg(20);
BENCHMARK_CAPTURE(Grid, eigen, true)->Name("Kernel/grid-eigen")->Arg(5)->Arg(10)->Arg(20);
BENCHMARK_CAPTURE(Mould, rm, false)->Name("Kernel/mould-row-major")->Arg(10)->Arg(20);
BENCHMARK_CAPTURE(Mould, eigen, true)->Name("Kernel/mould-eigen")->Arg(10)->Arg(20);
BENCHMARK_CAPTURE(Rows, rm, false)->Name("Kernel/rows-row-major")->DenseRange(1, 4);
BENCHMARK_CAPTURE(Rows, eigen, true)->Name("Kernel/rows-eigen")->DenseRange(1, 4);
