// The Dirichlet extremal on a patch complex (solvers/complex/complex_extremal.h), the disc over a
// wavy closed curve on the tensor O-grid (5 patches) refined in h r times (5 · 4^r patches):
//   ComplexExtremal/<n>/<r>   assemble the sparse Gram, factor (CHOLMOD), solve;
//   ComplexRefine/<n>/<r>     r h-refinements of the 5-patch complex (de Casteljau subdivision).
// The cost at fixed degree should grow about linearly with the patch count.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

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
