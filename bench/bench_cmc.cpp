// CMC solve time (seed 004): routes Cmc/<solver>/<n> for one solve of the triangular problem with
// sphere (inverse stereographic, conformal) boundary data at H = 1, and Cmc/dirichlet/<n> for the
// Dirichlet extremal (the linear solve, H = 0) as the baseline. The per-degree setup (Gram and
// volume quadrature tables) is cached by CmcFunctional and built before timing.
#include <benchmark/benchmark.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/bernstein.h"
#include "energies/cmc.h"
#include "solvers/cmc.h"

namespace {

using namespace bpde;

Eigen::Vector3d sphere(double u, double v) {
  const double s = u - 1.0 / 3, t = v - 1.0 / 3, r2 = s * s + t * t;
  return Eigen::Vector3d(2 * s, 2 * t, r2 - 1) / (1 + r2);
}

Eigen::MatrixX3d fit(int n, double u0, double v0, double u1, double v1) {
  Eigen::MatrixXd A(n + 1, n + 1);
  Eigen::MatrixX3d rhs(n + 1, 3);
  std::vector<double> b(static_cast<size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    const double t = 0.5 * (1 - std::cos(std::numbers::pi * k / n));
    bernstein_values(n, t, b.data());
    for (int i = 0; i <= n; ++i) A(k, i) = b[static_cast<size_t>(i)];
    rhs.row(k) = sphere(u0 + (u1 - u0) * t, v0 + (v1 - v0) * t).transpose();
  }
  return A.partialPivLu().solve(rhs);
}

TriangularNet sphere_data(int n) {
  TriangularNet net(n);
  const Eigen::MatrixX3d e1 = fit(n, 0, 0, 1, 0), e2 = fit(n, 0, 0, 0, 1), e3 = fit(n, 0, 1, 1, 0);
  for (int i = 0; i <= n; ++i) {
    net.set_point(i, 0, e1.row(i).transpose());
    net.set_point(0, i, e2.row(i).transpose());
    net.set_point(i, n - i, e3.row(i).transpose());
  }
  return net;
}

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
