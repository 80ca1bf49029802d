// The cost of a job's report beside the cost of its solve (docs/performance.md, "where users feel it"):
//   Solve/<kind>/<n>    run_job (or run_blend): the solve and the report quantities the solver
//                       computes (energy, pde_residual), with the per-degree caches warm;
//   Report/<kind>/<n>   write_job_result (or write_blend_outcome) into a temporary folder: the one
//                       tabulated sampling of the surface (sample_net), the mean-curvature
//                       statistics of that mesh, the CGAL checks, result.json and the three files.
// Kinds: pde (tensor biharmonic, method lu), extremal (tensor biharmonic, boundary fixed),
// cmc (triangular, sphere boundary, H = 1, newton), blend (k x k partition, no data points, the
// parameter is k). Every job samples at 50 (the default). Compare Report/<kind>/<n> with
// Solve/<kind>/<n> in the same run (docs/performance_measurements.md, "Reports and solves").
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_data.h"
#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/jobs/run_blend.h"
#include "bezierpde/jobs/run_job.h"

namespace {

using namespace bpde;

std::string scratch_dir() {
  static const std::string d = (std::filesystem::temp_directory_path() / "bpde_bench_report").string();
  return d;
}

void SolveJob(benchmark::State& state, const std::string& kind) {
  const Job job = bpde_bench::job(kind, static_cast<int>(state.range(0)));
  run_job(job);  // warm the per-degree caches
  for (auto _ : state) benchmark::DoNotOptimize(run_job(job));
}

void ReportJob(benchmark::State& state, const std::string& kind) {
  const Job job = bpde_bench::job(kind, static_cast<int>(state.range(0)));
  const SolveOutcome out = run_job(job);
  for (auto _ : state) benchmark::DoNotOptimize(write_job_result(scratch_dir(), job, out));
}

void SolveBlend(benchmark::State& state) {
  const BlendConfig c = bpde_bench::blend_config(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(run_blend(c));
}

void ReportBlend(benchmark::State& state) {
  const BlendConfig c = bpde_bench::blend_config(static_cast<int>(state.range(0)));
  const BlendOutcome out = run_blend(c);
  for (auto _ : state) benchmark::DoNotOptimize(write_blend_outcome(scratch_dir(), c, out));
}

void Degrees(benchmark::internal::Benchmark* b) {
  for (int n : {5, 10, 15, 20, 25}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}
void CmcDegrees(benchmark::internal::Benchmark* b) {
  for (int n : {6, 10, 16, 20}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}
void BlendSizes(benchmark::internal::Benchmark* b) {
  for (int k : {8, 16, 32}) b->Arg(k);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_CAPTURE(SolveJob, pde, std::string("pde"))->Name("Solve/pde")->Apply(Degrees);
BENCHMARK_CAPTURE(ReportJob, pde, std::string("pde"))->Name("Report/pde")->Apply(Degrees);
BENCHMARK_CAPTURE(SolveJob, extremal, std::string("extremal"))->Name("Solve/extremal")->Apply(Degrees);
BENCHMARK_CAPTURE(ReportJob, extremal, std::string("extremal"))->Name("Report/extremal")->Apply(Degrees);
BENCHMARK_CAPTURE(SolveJob, cmc, std::string("cmc"))->Name("Solve/cmc")->Apply(CmcDegrees);
BENCHMARK_CAPTURE(ReportJob, cmc, std::string("cmc"))->Name("Report/cmc")->Apply(CmcDegrees);
BENCHMARK(SolveBlend)->Name("Solve/blend")->Apply(BlendSizes);
BENCHMARK(ReportBlend)->Name("Report/blend")->Apply(BlendSizes);

namespace {

// Check/<kind>/<n>: the pairwise self-intersection tests of the CGAL checks (check_mesh of the
// sampled mesh with the projection proof off), with the grid broad phase (the default) and with
// CGAL::box_self_intersection_d (Check-cgal-boxes/<kind>/<n>); Check-report/<kind>/<n>: the checks
// as check_report runs them (the projection proof first, checks/mesh_checks.h), for the tensor
// kinds of Report/<kind>/<n>.
void CheckJob(benchmark::State& state, const std::string& kind, bpde::BroadPhase broad_phase, bool proof) {
  using namespace bpde;
  const Job job = bpde_bench::job(kind, static_cast<int>(state.range(0)));
  const TriangleMesh mesh = sample_net(run_job(job).net, job.samples);
  std::vector<double> V;
  std::vector<int> F;
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V.push_back(mesh.V(r, c));
  for (Eigen::Index r = 0; r < mesh.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F.push_back(mesh.F(r, c));
  MeshCheckReport rep;
  MeshCheckOptions options;
  options.broad_phase = broad_phase;
  options.projection_proof = proof;
  for (auto _ : state) benchmark::DoNotOptimize(rep = check_mesh(V, F, options));
  state.counters["box_pairs"] = static_cast<double>(rep.box_pairs);
  state.counters["self_intersections"] = rep.self_intersections;
  state.counters["embedded_by_projection"] = rep.embedded_by_projection ? 1 : 0;
}

}  // namespace

BENCHMARK_CAPTURE(CheckJob, pde, std::string("pde"), bpde::BroadPhase::kGrid, false)->Name("Check/pde")->Apply(Degrees);
BENCHMARK_CAPTURE(CheckJob, pde_cgal, std::string("pde"), bpde::BroadPhase::kCgalBoxes, false)
    ->Name("Check-cgal-boxes/pde")
    ->Apply(Degrees);
BENCHMARK_CAPTURE(CheckJob, pde_report, std::string("pde"), bpde::BroadPhase::kGrid, true)
    ->Name("Check-report/pde")
    ->Apply(Degrees);
BENCHMARK_CAPTURE(CheckJob, cmc, std::string("cmc"), bpde::BroadPhase::kGrid, false)->Name("Check/cmc")->Apply(CmcDegrees);
BENCHMARK_CAPTURE(CheckJob, cmc_cgal, std::string("cmc"), bpde::BroadPhase::kCgalBoxes, false)
    ->Name("Check-cgal-boxes/cmc")
    ->Apply(CmcDegrees);
BENCHMARK_CAPTURE(CheckJob, cmc_report, std::string("cmc"), bpde::BroadPhase::kGrid, true)
    ->Name("Check-report/cmc")
    ->Apply(CmcDegrees);
