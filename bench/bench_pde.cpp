// Table 1 of Arnal–Monterde–Ugail (explicit PDE solutions, §7): biharmonic surface from a degree-n boundary, solve +
// evaluation on a 50x50 parametric mesh (TensorNet::evaluate_grid), n in {4,5,8,10,12,15,18,20}.
//   Biharmonic/explicit/<n>      closed form (solvers/pde/pde_explicit.h) + evaluation
//   Biharmonic/lu/<n>            the "lu" method (solvers/pde/pde_lu.h): build and solve the
//                                block-triangular anti-diagonal system, O(n^3) + evaluation
//   Biharmonic/lu-bernstein/<n>  the dense Bernstein least-squares system built and factored in
//                                long double each time, O(n^6) + evaluation: the classical
//                                "linear system" column of the paper, done accurately
//   Biharmonic/mould/<n>         PdeMould built once outside the loop; per solve one matrix
//                                product + evaluation
//   Biharmonic/mould-build/<n>   building the mould alone (factor once, precompute S)
// The boundary is our own smooth degree-n ring (a Fig. 1-like saddle), the same for all routes.
#include <benchmark/benchmark.h>

#include <cmath>

#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/tensor/tensor_net.h"

namespace {

bpde::TensorNet fig1_like_boundary(int n) {
  bpde::TensorNet net(n, n);
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      if (i != 0 && i != n && j != 0 && j != n) continue;
      const double u = double(i) / n, v = double(j) / n;
      net.set_point(i, j,
                    Eigen::Vector3d(u + 0.1 * std::sin(pi * v), v + 0.1 * std::sin(2 * pi * u),
                                    0.4 * std::sin(pi * u) * std::cos(pi * v) + 0.2 * (u - v)));
    }
  return net;
}

const Eigen::VectorXd& mesh50() {
  static const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(50, 0.0, 1.0);
  return t;
}

void Explicit(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet data = fig1_like_boundary(n);
  const bpde::EnergySpec op = bpde::EnergySpec::biharmonic();
  for (auto _ : state) {
    const bpde::PdeSolution s = bpde::solve_pde_explicit(data, op);
    benchmark::DoNotOptimize(s.net.evaluate_grid(mesh50(), mesh50()));
  }
}

void Lu(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet data = fig1_like_boundary(n);
  const bpde::EnergySpec op = bpde::EnergySpec::biharmonic();
  for (auto _ : state) {
    const bpde::PdeSolution s = bpde::solve_pde_lu(data, op);
    benchmark::DoNotOptimize(s.net.evaluate_grid(mesh50(), mesh50()));
  }
}

void LuBernstein(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet data = fig1_like_boundary(n);
  const bpde::EnergySpec op = bpde::EnergySpec::biharmonic();
  bpde::PdeLuOptions o;
  o.formulation = bpde::PdeLuOptions::Formulation::Bernstein;
  for (auto _ : state) {
    const bpde::PdeSolution s = bpde::solve_pde_lu(data, op, o);
    benchmark::DoNotOptimize(s.net.evaluate_grid(mesh50(), mesh50()));
  }
}

void Mould(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bpde::TensorNet data = fig1_like_boundary(n);
  const bpde::PdeMould mould(bpde::EnergySpec::biharmonic(), n, n);
  bpde::TensorNet out(n, n);
  for (auto _ : state) {
    mould.apply(data, out);
    benchmark::DoNotOptimize(out.evaluate_grid(mesh50(), mesh50()));
  }
}

void MouldBuild(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const bpde::PdeMould mould(bpde::EnergySpec::biharmonic(), n, n);
    benchmark::DoNotOptimize(mould.interior_from_boundary().data());
  }
}

void Table1Degrees(benchmark::internal::Benchmark* b) {
  for (int n : {4, 5, 8, 10, 12, 15, 18, 20}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(Explicit)->Name("Biharmonic/explicit")->Apply(Table1Degrees);
BENCHMARK(Lu)->Name("Biharmonic/lu")->Apply(Table1Degrees);
BENCHMARK(LuBernstein)->Name("Biharmonic/lu-bernstein")->Apply(Table1Degrees);
BENCHMARK(Mould)->Name("Biharmonic/mould")->Apply(Table1Degrees);
BENCHMARK(MouldBuild)->Name("Biharmonic/mould-build")->Apply(Table1Degrees);
