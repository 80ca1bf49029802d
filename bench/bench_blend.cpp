// Smoothing PDE splines (Pasadas–Rodríguez): the solve of a blend on a k x k partition
// (bench/bench_data.h blend_config: smooth edges, no data points), by each linear solver:
//   Blend/cholesky/<k>  the default: the reduced SPD system by sparse Cholesky (CHOLMOD supernodal
//                       with its fill-reducing ordering; Eigen SimplicialLDLT without CHOLMOD);
//   Blend/kkt/<k>       the KKT system of eq. (8) by SparseLU (COLAMD), the former default.
// Memory is not measured here (Google Benchmark has no per-run peak): docs/performance_measurements.md gives
// the peak RSS of `bpde blend` from /usr/bin/time for the same configs.
#include <benchmark/benchmark.h>

#include "bench_data.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"

namespace {

using namespace bpde;

void run(benchmark::State& state, SmoothingSplineOptions::Method m) {
  const BlendConfig c = bpde_bench::blend_config(static_cast<int>(state.range(0)));
  SmoothingSplineOptions o;
  o.method = m;
  for (auto _ : state) {
    const SmoothingSplineResult r = solve_smoothing_spline(c.problem, o);
    if (!r.summary.converged) state.SkipWithError(r.summary.message.c_str());
    benchmark::DoNotOptimize(r.functional);
  }
}

void Cholesky(benchmark::State& s) { run(s, SmoothingSplineOptions::Method::kElimination); }
void Kkt(benchmark::State& s) { run(s, SmoothingSplineOptions::Method::kKktLu); }

}  // namespace

BENCHMARK(Cholesky)->Name("Blend/cholesky")->RangeMultiplier(2)->Range(8, 128)->Unit(benchmark::kMillisecond);
BENCHMARK(Kkt)->Name("Blend/kkt")->RangeMultiplier(2)->Range(8, 128)->Unit(benchmark::kMillisecond);
