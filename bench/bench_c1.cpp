// Centella–Monterde–Moreno–Oset (C¹ methods and the clamped plate). Routes: Tetraharmonic/{explicit,lu}/<n>,
// Tetraharmonic/lu-unrefined/<n> (lu without the per-solve refinement; counter residual on all three),
// BiharmonicLoad/lu/<n>, Plate/{ritz,admissible-load}/<n>.
// The lu solvers build their solution operator once per degree (cached per process); these
// routes time the steady state (docs/c1.md lists the one-time setup cost).
#include <benchmark/benchmark.h>

#include <cmath>

#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/clamped_plate.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"

namespace {

using namespace bpde;

TensorNet c1_data(int n) {
  TensorNet d(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = i / double(n), v = j / double(n);
      d.set_point(i, j, Eigen::Vector3d(u, v, std::sin(3 * u) * std::cos(2 * v)));
    }
  return d;
}

// Counter `residual`: the relative residual of Δ⁴x the solve reports (what the refinement buys).
void tetraharmonic(benchmark::State& state, TetraharmonicOptions::Method m, bool refine = true) {
  const TensorNet data = c1_data(static_cast<int>(state.range(0)));
  TetraharmonicOptions o;
  o.method = m;
  o.refine = refine;
  const TetraharmonicResult first = solve_tetraharmonic(data, o);  // builds the cached operator (untimed)
  for (auto _ : state) benchmark::DoNotOptimize(solve_tetraharmonic(data, o));
  state.counters["residual"] = first.summary.residual;
}

void BM_TetraExplicit(benchmark::State& s) { tetraharmonic(s, TetraharmonicOptions::Method::Explicit); }
void BM_TetraLu(benchmark::State& s) { tetraharmonic(s, TetraharmonicOptions::Method::LU); }
void BM_TetraLuUnrefined(benchmark::State& s) { tetraharmonic(s, TetraharmonicOptions::Method::LU, false); }

void BM_BiharmonicLoad(benchmark::State& state) {
  const TensorNet data = c1_data(static_cast<int>(state.range(0)));
  benchmark::DoNotOptimize(solve_biharmonic_load(data));  // builds the cached operator (untimed)
  for (auto _ : state) benchmark::DoNotOptimize(solve_biharmonic_load(data));
}

void plate(benchmark::State& state, ClampedPlateOptions::Method m) {
  ClampedPlateOptions o;
  o.degree = static_cast<int>(state.range(0));
  o.method = m;
  for (auto _ : state) benchmark::DoNotOptimize(solve_clamped_plate(o).center_deflection);
}
void BM_PlateRitz(benchmark::State& s) { plate(s, ClampedPlateOptions::Method::Ritz); }
void BM_PlateAdmissible(benchmark::State& s) { plate(s, ClampedPlateOptions::Method::AdmissibleLoad); }

BENCHMARK(BM_TetraExplicit)->Name("Tetraharmonic/explicit")->DenseRange(7, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TetraLu)->Name("Tetraharmonic/lu")->DenseRange(7, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TetraLuUnrefined)->Name("Tetraharmonic/lu-unrefined")->DenseRange(12, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BiharmonicLoad)->Name("BiharmonicLoad/lu")->DenseRange(7, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlateRitz)
    ->Name("Plate/ritz")
    ->Arg(7)
    ->Arg(9)
    ->Arg(11)
    ->Arg(15)
    ->Arg(20)
    ->Arg(25)
    ->Arg(30)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlateAdmissible)
    ->Name("Plate/admissible-load")
    ->Arg(7)
    ->Arg(9)
    ->Arg(11)
    ->Arg(15)
    ->Arg(20)
    ->Arg(25)
    ->Arg(30)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
