// How each main job grows with its size (docs/performance_measurements.md "Scaling"): one whole job as a user
// runs it, once per process (Iterations(1): the per-degree caches are cold, as in `bpde solve`):
//   Scaling/<kind>/<n>   run_job + write_job_result (solve, report, result.json and the files);
//   Scaling/blend/<k>    run_blend + write_blend_outcome on a k x k partition.
// Kinds (bench/bench_data.h job()): pde and extremal (tensor, n = 5..30), cmc (triangular,
// n = 4..25), bspline (spans 2..64). scripts/scaling.py runs each in its own process under
// /usr/bin/time (peak memory) and fits the exponents of time and memory.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "bench_data.h"
#include "bezierpde/jobs/run_blend.h"

namespace {

using namespace bpde;

std::string scratch_dir() {
  static const std::string d = (std::filesystem::temp_directory_path() / "bpde_bench_scaling").string();
  return d;
}

void WholeJob(benchmark::State& state, const std::string& kind) {
  const bpde::Job job = bpde_bench::job(kind, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(write_job_result(scratch_dir(), job, run_job(job)));
}

void Blend(benchmark::State& state) {
  const BlendConfig c = bpde_bench::blend_config(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(write_blend_outcome(scratch_dir(), c, run_blend(c)));
}

void Tensor(benchmark::internal::Benchmark* b) {
  for (int n = 5; n <= 30; n += 5) b->Arg(n);
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}
void Cmc(benchmark::internal::Benchmark* b) {
  for (int n : {4, 6, 8, 10, 12, 15, 18, 20, 25}) b->Arg(n);
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}
void Spans(benchmark::internal::Benchmark* b) {
  for (int s : {2, 4, 8, 16, 32, 64}) b->Arg(s);
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}
void Partitions(benchmark::internal::Benchmark* b) {
  for (int k = 8; k <= BfsSpace::kMaxPartition; k *= 2) b->Arg(k);
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_CAPTURE(WholeJob, pde, std::string("pde"))->Name("Scaling/pde")->Apply(Tensor);
BENCHMARK_CAPTURE(WholeJob, extremal, std::string("extremal"))->Name("Scaling/extremal")->Apply(Tensor);
BENCHMARK_CAPTURE(WholeJob, cmc, std::string("cmc"))->Name("Scaling/cmc")->Apply(Cmc);
BENCHMARK_CAPTURE(WholeJob, bspline, std::string("bspline"))->Name("Scaling/bspline")->Apply(Spans);
BENCHMARK(Blend)->Name("Scaling/blend")->Apply(Partitions);
