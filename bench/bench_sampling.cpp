// Sampling benchmarks: tabulated evaluation against pointwise de Casteljau.
//   Sample/tensor-grid/<n>        50x50 grid (2601 points) of a degree-(n,n) patch, tensor structure:
//                                 one Bernstein table per direction + two small products.
//   Sample/tensor-casteljau/<n>   the same 2601 points by per-point de Casteljau (baseline).
//   Sample/triangular-basis/<n>   1326 points (N = 50) of a degree-n triangular patch, basis matrix.
//   Sample/triangular-casteljau/<n>  the same points by per-point de Casteljau (baseline).
// Compare the ratios of the pairs in the same run.
#include <benchmark/benchmark.h>

#include <random>

#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace {

bpde::TensorNet random_tensor(int n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  bpde::TensorNet net(n, n);
  for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
  return net;
}

bpde::TriangularNet random_triangular(int n) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> U(-1, 1);
  bpde::TriangularNet net(n);
  for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
  return net;
}

void TensorGrid(benchmark::State& state) {
  const auto net = random_tensor(static_cast<int>(state.range(0)));
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(51, 0, 1);
  for (auto _ : state) benchmark::DoNotOptimize(net.evaluate_grid(t, t));
  state.SetItemsProcessed(state.iterations() * 51 * 51);
}

void TensorCasteljau(benchmark::State& state) {
  const auto net = random_tensor(static_cast<int>(state.range(0)));
  Eigen::MatrixX3d out(51 * 51, 3);
  for (auto _ : state) {
    for (int a = 0; a <= 50; ++a)
      for (int b = 0; b <= 50; ++b) out.row(a * 51 + b) = net.evaluate(a / 50.0, b / 50.0).transpose();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * 51 * 51);
}

void TriangularBasis(benchmark::State& state) {
  const auto net = random_triangular(static_cast<int>(state.range(0)));
  const Eigen::MatrixX2d uv = bpde::triangular_sample_parameters(50);  // 1326 points
  for (auto _ : state) benchmark::DoNotOptimize(net.evaluate_many(uv));
  state.SetItemsProcessed(state.iterations() * uv.rows());
}

void TriangularCasteljau(benchmark::State& state) {
  const auto net = random_triangular(static_cast<int>(state.range(0)));
  const Eigen::MatrixX2d uv = bpde::triangular_sample_parameters(50);
  Eigen::MatrixX3d out(uv.rows(), 3);
  for (auto _ : state) {
    for (Eigen::Index k = 0; k < uv.rows(); ++k) out.row(k) = net.evaluate(uv(k, 0), uv(k, 1)).transpose();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * uv.rows());
}

}  // namespace

BENCHMARK(TensorGrid)->Name("Sample/tensor-grid")->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(TensorCasteljau)->Name("Sample/tensor-casteljau")->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(TriangularBasis)->Name("Sample/triangular-basis")->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(TriangularCasteljau)
    ->Name("Sample/triangular-casteljau")
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Unit(benchmark::kMicrosecond);
