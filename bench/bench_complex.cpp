// The Dirichlet extremal on a patch complex (solvers/complex/complex_extremal.h), the disc over a
// wavy closed curve on the tensor O-grid (5 patches) refined in h r times (5 · 4^r patches):
//   ComplexExtremal/<n>/<r>   assemble the sparse Gram, factor (CHOLMOD), solve;
//   ComplexRefine/<n>/<r>     r h-refinements of the 5-patch complex (de Casteljau subdivision).
// The cost at fixed degree should grow about linearly with the patch count.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>

#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"

namespace {

bpde::PatchComplex wavy_disc(int n) {
  const bpde::BoundaryCurve c = bpde::BoundaryCurve::function([](double t) {
    const double a = 2 * std::numbers::pi * t;
    return Eigen::Vector3d(std::cos(a), std::sin(a), 0.2 * std::sin(3 * a));
  });
  return bpde::loop_complex(bpde::PatchKind::tensor, n, {{c}}).complex;
}

void BM_ComplexExtremal(benchmark::State& state) {
  bpde::PatchComplex c = wavy_disc(static_cast<int>(state.range(0)));
  for (int r = 0; r < state.range(1); ++r) c = bpde::refine_h(c);
  for (auto _ : state) {
    const bpde::ComplexExtremal e = bpde::solve_complex_extremal(c, bpde::EnergySpec::dirichlet());
    benchmark::DoNotOptimize(e.energy);
  }
  state.counters["patches"] = static_cast<double>(c.patches.size());
}

void BM_ComplexRefine(benchmark::State& state) {
  const bpde::PatchComplex c = wavy_disc(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    bpde::PatchComplex h = c;
    for (int r = 0; r < state.range(1); ++r) h = bpde::refine_h(h);
    benchmark::DoNotOptimize(h.points.data());
  }
}

}  // namespace

BENCHMARK(BM_ComplexExtremal)->Name("ComplexExtremal")->ArgsProduct({{4, 8}, {0, 1, 2, 3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ComplexRefine)->Name("ComplexRefine")->ArgsProduct({{4, 8}, {1, 2, 3}})->Unit(benchmark::kMillisecond);

// ---- The area functional on complexes (solvers/cmc/complex_cmc.h)
//
// The catenoid between the unit circles at z = ±1/2 (H = 0, A = 5.99179697580228): the annulus
// layout (a ring of 4 tensor patches) at degree 4 refined in h r times, 4 · 4^r patches:
//   CmcComplex/minimal/<patches>    the area solve (minimal-surface route, sparse Hessians and
//                                   CHOLMOD factors) to the tolerance 1e-10, from the data net to
//                                   the converged net (at 1e-11 the 256 patches end 1.8e-11 short
//                                   after the corrector's 60 iterations: its linear crawl along the
//                                   tangential valley);
//   CmcComplex/extremal/<patches>   the Dirichlet extremal of the same complex (one sparse
//                                   Cholesky solve): the baseline of the ratio.
// At fixed degree the ratio should stay about constant as the patches grow (both linear); the
// 1024-patch row takes about 6 s.
namespace {

bpde::PatchComplex catenoid_ring(int refinements) {
  const bpde::BoundaryCurve top = bpde::BoundaryCurve::circle({0, 0, 0.5}, {0, 0, 1}, 1.0);
  const bpde::BoundaryCurve bottom = bpde::BoundaryCurve::circle({0, 0, -0.5}, {0, 0, -1}, 1.0);
  bpde::LoopOptions options;
  options.method = bpde::FitMethod::Geometric;  // as an area job fits its boundary (FORMATS.md)
  bpde::PatchComplex c = bpde::loop_complex(bpde::PatchKind::tensor, 4, {{top}, {bottom}}, options).complex;
  for (int r = 0; r < refinements; ++r) c = bpde::refine_h(c);
  return c;
}

int refinements_for(int patches) {
  int r = 0;
  for (int p = 4; p < patches; p *= 4) ++r;
  return r;
}

void BM_CmcComplexMinimal(benchmark::State& state) {
  const bpde::PatchComplex c = catenoid_ring(refinements_for(static_cast<int>(state.range(0))));
  bpde::CmcOptions o;
  o.functional = bpde::CmcFunctionalKind::Area;
  o.H = 0.0;
  o.tolerance = 1e-10;  // the crawl of the corrector along the tangential valley below it is linear
  double A = 0.0;
  bool converged = false;
  std::string message;
  for (auto _ : state) {
    const bpde::CmcResult<bpde::PatchComplex> r = bpde::solve_cmc(c, o);
    A = r.A;
    converged = r.summary.converged;
    message = r.summary.message;
    benchmark::DoNotOptimize(A);
  }
  if (!converged) state.SkipWithError(message.c_str());
  state.counters["patches"] = static_cast<double>(c.patches.size());
  state.counters["area_error"] = std::abs(A - 5.99179697580228);
}

void BM_CmcComplexExtremal(benchmark::State& state) {
  const bpde::PatchComplex c = catenoid_ring(refinements_for(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    const bpde::ComplexExtremal e = bpde::solve_complex_extremal(c, bpde::EnergySpec::dirichlet());
    benchmark::DoNotOptimize(e.energy);
  }
  state.counters["patches"] = static_cast<double>(c.patches.size());
}

}  // namespace

BENCHMARK(BM_CmcComplexMinimal)->Name("CmcComplex/minimal")->Arg(16)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CmcComplexExtremal)->Name("CmcComplex/extremal")->Arg(16)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);
