#pragma once
// Problem data shared by the benchmarks (bench/bench_report.cpp, bench/bench_blend.cpp,
// bench/bench_scaling.cpp).
#include <cmath>

#include <string>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde_bench {

/// A degree-(n, n) net whose every point lies on a smooth saddle-like surface (a Fig. 1-like ring of
/// Arnal–Monterde–Ugail when only the boundary is used).
inline bpde::TensorNet saddle_ring(int n) {
  bpde::TensorNet net(n, n);
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      net.set_point(i, j,
                    Eigen::Vector3d(u + 0.1 * std::sin(pi * v), v + 0.1 * std::sin(2 * pi * u),
                                    0.4 * std::sin(pi * u) * std::cos(pi * v) + 0.2 * (u - v)));
    }
  return net;
}

/// A blend config on a k x k partition: smooth edges y = 0 and y = 1, no data points, samples 50.
inline bpde::BlendConfig blend_config(int k) {
  bpde::BlendConfig c;
  bpde::SmoothingSplineProblem& p = c.problem;
  p.k = p.l = k;
  p.y0_value.resize(k + 1, 3);
  p.y1_value.resize(k + 1, 3);
  p.y0_dy.resize(k + 1, 3);
  p.y1_dy.resize(k + 1, 3);
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= k; ++i) {
    const double x = double(i) / k;
    p.y0_value.row(i) << x, 0.0, 0.2 * std::sin(pi * x);
    p.y1_value.row(i) << x, 1.0, 0.3 * std::cos(pi * x);
    p.y0_dy.row(i) << 0.0, 1.0, 0.5;
    p.y1_dy.row(i) << 0.0, 1.0, -0.5;
  }
  p.points.resize(0, 2);
  p.data.resize(0, 3);
  return c;
}

/// A bicubic B-spline net with s x s uniform spans: the plane grid lifted by a smooth wave.
inline bpde::BSplineNet wavy_bspline(int spans, int p = 3) {
  std::vector<double> K(p, 0.0);
  for (int s = 0; s <= spans; ++s) K.push_back(static_cast<double>(s) / spans);
  K.insert(K.end(), p, 1.0);
  const int n = static_cast<int>(K.size()) - p - 1;
  Eigen::MatrixX3d P(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      P.row(i * n + j) << static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1),
          0.2 * std::sin(3.0 * i / n) * std::cos(2.0 * j / n);
  return bpde::BSplineNet(p, p, K, K, P);
}

/// A validated job of one of the kinds of the report and scaling benchmarks:
///   pde       tensor degree (n, n), biharmonic, method lu, the saddle ring;
///   extremal  tensor degree (n, n), biharmonic energy, boundary fixed, the saddle ring;
///   cmc       triangular degree n, the sphere's boundary (conformal), H = 1, newton;
///   bspline   bicubic B-spline with n x n spans, biharmonic extremal, boundary fixed.
/// Every job samples at 50.
inline bpde::Job job(const std::string& kind, int n) {
  using namespace bpde;
  Job job;
  if (kind == "cmc") {
    job.net = triangular_boundary(n, sphere_triangle);
    job.problem.kind = ProblemKind::CmcH;
    job.problem.H = 1.0;
    job.problem.solver = CmcSolver::Newton;
  } else {
    if (kind == "bspline")
      job.net = wavy_bspline(n);
    else
      job.net = saddle_ring(n);
    job.problem.kind = kind == "pde" ? ProblemKind::Pde : ProblemKind::Extremal;
    job.problem.energy = EnergySpec::biharmonic();
    job.problem.method = PdeMethod::Lu;
  }
  validate_job(job);
  return job;
}

}  // namespace bpde_bench
