// CMC solve time (Arnal–Lluch–Monterde, triangular CMC): routes Cmc/<solver>/<n> for one solve of the triangular
// problem with sphere (inverse stereographic, conformal) boundary data at H = 1, and Cmc/dirichlet/<n> for the
// Dirichlet extremal (the linear solve, H = 0) as the baseline. The per-degree setup (Gram and
// volume quadrature tables) is cached by CmcFunctional and built before timing.
#include <benchmark/benchmark.h>

#include "boundaries/reference_boundaries.h"
#include "energies/cmc.h"
#include "solvers/cmc/cmc.h"

namespace {

using namespace bpde;

// The unit sphere's boundary over the reference triangle (conformal data, H = +1).
TriangularNet sphere_data(int n) { return triangular_boundary(n, sphere_triangle); }

void run(benchmark::State& state, CmcSolver solver, bool dirichlet) {
  const int n = static_cast<int>(state.range(0));
  const TriangularNet data = sphere_data(n);
  CmcFunctional::cached_triangular(n);
  CmcOptions o;
  o.H = 1.0;
  o.solver = solver;
  int steps = 0, iters = 0;
  for (auto _ : state) {
    if (dirichlet) {
      benchmark::DoNotOptimize(dirichlet_extremal(data, FixedSet::Boundary));
    } else {
      const auto r = solve_cmc(data, o);
      if (!r.summary.converged) state.SkipWithError(r.summary.message.c_str());
      steps = r.continuation_steps;
      iters = r.summary.iterations;
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["steps"] = steps;
  state.counters["iterations"] = iters;
}

void Dirichlet(benchmark::State& s) { run(s, CmcSolver::Newton, true); }
void Newton(benchmark::State& s) { run(s, CmcSolver::Newton, false); }
void Ceres(benchmark::State& s) { run(s, CmcSolver::Ceres, false); }
void NLopt(benchmark::State& s) { run(s, CmcSolver::NLopt, false); }

}  // namespace

BENCHMARK(Dirichlet)->Name("Cmc/dirichlet")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(Newton)->Name("Cmc/newton")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(Ceres)->Name("Cmc/ceres")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(NLopt)->Name("Cmc/nlopt")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
