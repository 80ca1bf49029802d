// CMC solve time (Arnal–Lluch–Monterde, triangular CMC): routes Cmc/<solver>/<n> for one solve of the triangular
// problem with sphere (inverse stereographic, conformal) boundary data at H = 1, and Cmc/dirichlet/<n> for the
// Dirichlet extremal (the linear solve, H = 0) as the baseline; CmcArea/{newton,ceres}/<n> for the
// area functional A + 2HV on the same data, and CmcArea/{newton,ceres}-without-trust-region/<n> the
// same with CmcOptions::area_trust_region false; CmcArea/circle/<n> for the area functional on the
// non-conformal data of the paper's Fig. 1 (the unit circle in three arcs by angle, H = -0.5), the
// case of docs/cmc_evolver.md; CmcArea/folded/3 where the answer folds; CmcMeanCurvature/{newton,newton-plain,ceres}/circle/<n> for the
// least squares of the mean curvature on that circle (newton-plain: without geodesic
// acceleration), and {newton,ceres}-volume/circle/<n> for its V form. AreaForm/{gradient,rows-and-scale}/
// {triangle,square}/<n>: one evaluation of the area's first variation on the rule the solves take
// at that degree (q = 15 on the triangle, 2n + 4 on the square), all rows against the free rows
// with their scale (what every residual of the area route costs; the baseline is the full gradient);
// AreaForm/hessian/{triangle,square}/<n> the free block of the Hessian on the same rules, and
// AreaForm/{hessian,rows-and-scale}/triangle-graded/<n> and AreaForm/rows-and-scale/square-graded/<n> on
// the graded q = 64 rule of the nearly degenerate corners (docs/performance_measurements.md, "Design decisions").
// Degree/…/<n> (n = 6 … 16): the solve time against the degree with the FLOP counts of the
// dominant kernels (the "flops" counters, counted from the sizes; see DegreeFlops below):
// Degree/area the area solve of CmcArea/circle, Degree/area-{gradient,hessian} one residual pass
// (all free rows and their scales) and one free Hessian of the area on the rule that solve ends
// on, Degree/dh the D_H solve of Cmc/newton and Degree/dh-factor the Cholesky of its 3k x 3k
// Hessian (at H = 0). The per-degree setup (Gram and volume quadrature tables) is cached by
// CmcFunctional and built before timing; the area rules' tables are cached by AreaForm after the
// first iteration.
#include <benchmark/benchmark.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace {

using namespace bpde;

// The unit sphere's boundary over the reference triangle (conformal data, H = +1).
TriangularNet sphere_data(int n) { return triangular_boundary(n, sphere_triangle); }

void run(benchmark::State& state, CmcSolver solver, bool dirichlet, bool area = false, bool trust_region = true) {
  const int n = static_cast<int>(state.range(0));
  const TriangularNet data = sphere_data(n);
  CmcFunctional::cached_triangular(n);
  CmcOptions o;
  o.H = 1.0;
  o.solver = solver;
  if (area) o.functional = CmcFunctionalKind::Area;
  o.area_trust_region = trust_region;
  int steps = 0, iters = 0;
  double residual = 0, converged = 0;
  for (auto _ : state) {
    if (dirichlet) {
      benchmark::DoNotOptimize(dirichlet_extremal(data, FixedSet::Boundary));
    } else {
      const auto r = solve_cmc(data, o);
      // The area routes are timed also when they stop at their numerical limit (docs/cmc.md):
      // the counters say how far they got.
      if (!r.summary.converged && !area) state.SkipWithError(r.summary.message.c_str());
      residual = r.summary.residual;
      converged = r.summary.converged ? 1 : 0;
      steps = r.continuation_steps;
      iters = r.summary.iterations;
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["steps"] = steps;
  state.counters["iterations"] = iters;
  if (area) {
    state.counters["residual"] = residual;
    state.counters["converged"] = converged;
  }
}

void Dirichlet(benchmark::State& s) { run(s, CmcSolver::Newton, true); }
void Newton(benchmark::State& s) { run(s, CmcSolver::Newton, false); }
void Ceres(benchmark::State& s) { run(s, CmcSolver::Ceres, false); }
void NLopt(benchmark::State& s) { run(s, CmcSolver::NLopt, false); }
// The area functional A + 2HV on the same data (solvers/cmc/cmc.h, "The area functional"): the D_H
// solve above, then the vanishing-regulariser stages with the newton or the ceres corrector.
void AreaNewton(benchmark::State& s) { run(s, CmcSolver::Newton, false, true); }
void AreaCeres(benchmark::State& s) { run(s, CmcSolver::Ceres, false, true); }
// The same without the trust-region part of the soft-mode phase (CmcOptions::area_trust_region).
void AreaNewtonNoTrustRegion(benchmark::State& s) { run(s, CmcSolver::Newton, false, true, false); }
void AreaCeresNoTrustRegion(benchmark::State& s) { run(s, CmcSolver::Ceres, false, true, false); }

// volume: the V form, v0 the volume of the exact cap of H = -0.5 over the unit circle.
void CircleRoute(benchmark::State& state, CmcFunctionalKind functional, CmcSolver solver = CmcSolver::Newton,
                 bool geodesic = true, bool volume = false) {
  const int n = static_cast<int>(state.range(0));
  const TriangularNet data = circle_three_arcs(n);
  CmcFunctional::cached_triangular(n);
  CmcOptions o;
  o.H = -0.5;
  if (volume) {
    const double R = 2.0, h = R - std::sqrt(R * R - 1);
    o.V = std::numbers::pi * h * h * (3 * R - h) / 3;
    o.H = 0.0;
  }
  o.functional = functional;
  o.solver = solver;
  o.geodesic_acceleration = geodesic;
  int iters = 0;
  double residual = 0;
  for (auto _ : state) {
    const auto r = solve_cmc(data, o);
    if (!r.summary.converged) state.SkipWithError(r.summary.message.c_str());
    residual = r.summary.residual;
    iters = r.summary.iterations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["iterations"] = iters;
  state.counters["residual"] = residual;
}
void AreaCircle(benchmark::State& s) { CircleRoute(s, CmcFunctionalKind::Area); }
// The trust-region part of the soft-mode phase on and off where the soft-mode loop stops above the
// tolerance (the helicoid piece s = 0.3 + 0.7u, t = 1.2v at H = 0, start "dirichlet"): the
// counters say where each ends (converged 1 with it, numerical-limit at 6.75e-11 without it).
void HelicoidTrustRegion(benchmark::State& state, bool trust_region) {
  const int n = static_cast<int>(state.range(0));
  const TensorNet data = tensor_boundary(n, [](double u, double v) {
    const double s = 0.3 + 0.7 * u, t = 1.2 * v;
    return Eigen::Vector3d(s * std::cos(t), s * std::sin(t), t);
  });
  CmcOptions o;
  o.functional = CmcFunctionalKind::Area;
  o.area_start = AreaStart::Dirichlet;
  o.area_trust_region = trust_region;
  for (auto _ : state) {
    const CmcResult<TensorNet> r = solve_cmc(data, o);
    benchmark::DoNotOptimize(r.net.points().data());
    state.counters["converged"] = r.summary.converged ? 1 : 0;
    state.counters["residual"] = r.summary.residual;
    state.counters["trust_region_iterations"] = r.routes.phase_count(AreaPhase::TrustRegion);
  }
}
void AreaHelicoid(benchmark::State& s) { HelicoidTrustRegion(s, true); }
void AreaHelicoidNoTrustRegion(benchmark::State& s) { HelicoidTrustRegion(s, false); }
// The area functional where its answer folds (tests/cmc/test_cmc_area.cpp,
// FoldedParametrisationIsReportedAsDegenerate: a tensor boundary whose edge v = 0 retraces itself,
// H = 0, n = 3). Its rule is refined to q = 64 in vain (the integrand has a kink along the fold),
// so every residual runs on 32 768 nodes: the case of the per-thread node arrays
// (docs/performance_measurements.md, "Design decisions").
void AreaFolded(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TensorNet data = tensor_boundary(n, [](double u, double v) {
    const double x = u + 0.25 * std::sin(2 * std::numbers::pi * u) * (1 - v);
    return Eigen::Vector3d(x, v, 0.3 * x * v);
  });
  CmcOptions o;
  o.functional = CmcFunctionalKind::Area;
  for (auto _ : state) {
    const CmcResult<TensorNet> r = solve_cmc(data, o);
    benchmark::DoNotOptimize(r.net.points().data());
    state.counters["converged"] = r.summary.converged ? 1 : 0;
    state.counters["quadrature_points"] = r.quadrature_points;
  }
}
// The least squares of the mean curvature on the same circle (its residual is √Φ, tolerance 1e-6;
// it converges from n = 8 on at H = -0.5, docs/cmc.md).
// Solver newton is the library's own Levenberg–Marquardt loop, ceres the same residuals as one
// Ceres residual block per quadrature node (solvers/cmc/mean_curvature_ceres.cpp).
void MeanCurvatureCircle(benchmark::State& s) { CircleRoute(s, CmcFunctionalKind::MeanCurvature); }
void MeanCurvatureCircleCeres(benchmark::State& s) {
  CircleRoute(s, CmcFunctionalKind::MeanCurvature, CmcSolver::Ceres);
}
// The newton loop without geodesic acceleration (CmcOptions::geodesic_acceleration = false): plain
// Levenberg–Marquardt, the baseline of the accelerated default.
void MeanCurvatureCirclePlain(benchmark::State& s) {
  CircleRoute(s, CmcFunctionalKind::MeanCurvature, CmcSolver::Newton, false);
}

// The V form on the same circle: newton (the KKT step of levenberg_marquardt.h) and ceres (the free
// points on the manifold V = v0, mean_curvature_ceres.cpp).
void MeanCurvatureCircleVolume(benchmark::State& s) {
  CircleRoute(s, CmcFunctionalKind::MeanCurvature, CmcSolver::Newton, true, true);
}
void MeanCurvatureCircleVolumeCeres(benchmark::State& s) {
  CircleRoute(s, CmcFunctionalKind::MeanCurvature, CmcSolver::Ceres, true, true);
}

// The area's first variation on a catenoid piece's net (regular, non-conformal): the full N x 3
// gradient (the baseline) and the free rows with their scale (AreaProblem::residual_at).
void AreaFormRoute(benchmark::State& state, bool triangle, bool rows, bool hessian = false, bool graded = false) {
  // graded: the graded q = 64 rule (on the triangle, or on the square where !triangle).
  const int n = static_cast<int>(state.range(0));
  auto surface = [](double u, double v) {
    const double th = 1.2 * u, rho = 1.1 + 0.8 * v;
    return Eigen::Vector3d(rho * std::cos(th), rho * std::sin(th), std::acosh(rho));
  };
  const std::shared_ptr<const AreaForm> f =
      graded && triangle ? AreaForm::cached_triangular(n, 64, 3)
      : graded           ? AreaForm::cached_tensor(n, n, 64, 3)
      : triangle         ? AreaForm::cached_triangular(n, 15)
                         : AreaForm::cached_tensor(n, n, 2 * n + 4);
  // The boundary of the catenoid piece, the interior from the Dirichlet extremal (a regular net).
  const Eigen::MatrixX3d P =
      triangle ? dirichlet_extremal(triangular_boundary(n, surface), FixedSet::Boundary).points()
                         : dirichlet_extremal(tensor_boundary(n, surface), FixedSet::Boundary).points();
  std::vector<int> idx;
  for (int i = 0; i < f->size(); ++i)
    if (i % 3 != 0) idx.push_back(i);  // about the share of free points at these degrees
  Eigen::MatrixX3d G, S;
  for (auto _ : state) {
    if (hessian)
      benchmark::DoNotOptimize(f->hessian(P, idx));
    else if (rows)
      f->gradient_rows_and_scale(P, idx, &G, &S);
    else
      G = f->gradient(P);
    benchmark::DoNotOptimize(G);
  }
  state.counters["nodes"] = f->nodes();
}
void AreaGradientTriangle(benchmark::State& s) { AreaFormRoute(s, true, false); }
void AreaRowsTriangle(benchmark::State& s) { AreaFormRoute(s, true, true); }
void AreaGradientSquare(benchmark::State& s) { AreaFormRoute(s, false, false); }
void AreaRowsSquare(benchmark::State& s) { AreaFormRoute(s, false, true); }
void AreaHessianTriangle(benchmark::State& s) { AreaFormRoute(s, true, false, true); }
void AreaHessianSquare(benchmark::State& s) { AreaFormRoute(s, false, false, true); }
void AreaHessianGraded(benchmark::State& s) { AreaFormRoute(s, true, false, true, true); }
void AreaRowsGraded(benchmark::State& s) { AreaFormRoute(s, true, true, false, true); }
void AreaRowsSquareGraded(benchmark::State& s) { AreaFormRoute(s, false, true, false, true); }


// The solve time against the degree. FLOP counts of the kernels, counted from the sizes (a
// multiply-add is 2 flops; per-node work of O(1) per node and the O(k^2) scatter left out):
//   Q nodes of the rule, N = (n+1)(n+2)/2 control points, k = (n-1)(n-2)/2 free (boundary fixed);
//   area residual pass (AreaForm::gradient_rows_and_scale): x_u, x_v at the nodes by 6 GEMV
//     passes over the Q x N basis tables (12 Q N), and per free row 4 dot products of length Q
//     per coordinate for the row and its scale (24 Q k): 12 Q N + 24 Q k;
//   area Hessian (AreaForm::hessian): the 2Q x 3k node matrix R filled (24 Q k), its rank update
//     R^T R on the lower triangle (2Q (3k)(3k+1)/2 multiply-adds: 18 Q k^2 + 6 Q k) and the three
//     k x k products B_u^T diag B_v (6 Q k^2): 24 Q k^2 + 30 Q k;
//   D_H Hessian factor (Cholesky of 3k x 3k): (3k)^3 / 3 = 9 k^3.
struct DegreeSizes {
  double N, k;
  explicit DegreeSizes(int n) : N((n + 1) * (n + 2) / 2.0), k((n - 1) * (n - 2) / 2.0) {}
};
double area_pass_flops(int n, double Q) {
  const DegreeSizes s(n);
  return 12 * Q * s.N + 24 * Q * s.k;
}
double area_hessian_flops(int n, double Q) {
  const DegreeSizes s(n);
  return 24 * Q * s.k * s.k + 30 * Q * s.k;
}
double dh_factor_flops(int n) {
  const double k = DegreeSizes(n).k;
  return 9 * k * k * k;
}

// q of the rule the circle's area solve ends on, per degree (filled by Degree/area, which runs
// first; a kernel route run alone solves once before timing).
std::map<int, int>& circle_rule() {
  static std::map<int, int> q;
  return q;
}
int circle_rule_q(int n) {
  auto it = circle_rule().find(n);
  if (it != circle_rule().end()) return it->second;
  CmcOptions o;
  o.H = -0.5;
  o.functional = CmcFunctionalKind::Area;
  return circle_rule()[n] = solve_cmc(circle_three_arcs(n), o).quadrature_points;
}

void DegreeArea(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TriangularNet data = circle_three_arcs(n);
  CmcFunctional::cached_triangular(n);
  CmcOptions o;
  o.H = -0.5;
  o.functional = CmcFunctionalKind::Area;
  int q = 0, iters = 0;
  double converged = 0;
  for (auto _ : state) {
    const auto r = solve_cmc(data, o);
    q = r.quadrature_points;
    iters = r.summary.iterations;
    converged = r.summary.converged ? 1 : 0;
    benchmark::DoNotOptimize(r);
  }
  circle_rule()[n] = q;
  const double Q = q > 0 ? AreaForm::cached_triangular(n, q)->nodes() : 0;
  state.counters["q"] = q;
  state.counters["nodes"] = Q;
  state.counters["iterations"] = iters;
  state.counters["converged"] = converged;
  state.counters["pass_flops"] = area_pass_flops(n, Q);
  state.counters["hessian_flops"] = area_hessian_flops(n, Q);
}

void DegreeAreaKernel(benchmark::State& state, bool hessian) {
  const int n = static_cast<int>(state.range(0));
  const int q = circle_rule_q(n);
  if (q <= 0) {
    state.SkipWithError("no rule");
    return;
  }
  const std::shared_ptr<const AreaForm> f = AreaForm::cached_triangular(n, q);
  const TriangularNet data = circle_three_arcs(n);
  const Eigen::MatrixX3d P = dirichlet_extremal(data, FixedSet::Boundary).points();
  const std::vector<int> idx = data.free_indices(FixedSet::Boundary);
  Eigen::MatrixX3d G, S;
  for (auto _ : state) {
    if (hessian) {
      benchmark::DoNotOptimize(f->hessian(P, idx));
    } else {
      f->gradient_rows_and_scale(P, idx, &G, &S);
      benchmark::DoNotOptimize(G.data());
    }
  }
  const double Q = f->nodes();
  state.counters["nodes"] = Q;
  state.counters["flops"] = benchmark::Counter(hessian ? area_hessian_flops(n, Q) : area_pass_flops(n, Q),
                                               benchmark::Counter::kIsIterationInvariantRate);
}
void DegreeAreaPass(benchmark::State& s) { DegreeAreaKernel(s, false); }
void DegreeAreaHessian(benchmark::State& s) { DegreeAreaKernel(s, true); }

void DegreeDh(benchmark::State& state) {
  run(state, CmcSolver::Newton, false);
  state.counters["factor_flops"] = dh_factor_flops(static_cast<int>(state.range(0)));
}

// The Cholesky of the D_H Hessian at H = 0 (the Dirichlet Gram over the free points ⊗ Id_3) at the
// Dirichlet extremal of the sphere's data: the factorisation of every fresh newton step.
void DegreeDhFactor(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TriangularNet data = sphere_data(n);
  const auto f = CmcFunctional::cached_triangular(n);
  const Eigen::MatrixX3d P = dirichlet_extremal(data, FixedSet::Boundary).points();
  const Eigen::MatrixXd Hs = f->hessian(P, 0.0, data.free_indices(FixedSet::Boundary));
  Eigen::LLT<Eigen::MatrixXd> llt(Hs.rows());
  for (auto _ : state) {
    llt.compute(Hs);
    benchmark::DoNotOptimize(llt.matrixLLT().data());
  }
  state.counters["flops"] = benchmark::Counter(dh_factor_flops(n), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(AreaGradientTriangle)->Name("AreaForm/gradient/triangle")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaRowsTriangle)->Name("AreaForm/rows-and-scale/triangle")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaGradientSquare)->Name("AreaForm/gradient/square")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaRowsSquare)->Name("AreaForm/rows-and-scale/square")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaHessianTriangle)->Name("AreaForm/hessian/triangle")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaHessianSquare)->Name("AreaForm/hessian/square")->Arg(6)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaHessianGraded)->Name("AreaForm/hessian/triangle-graded")->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaRowsGraded)->Name("AreaForm/rows-and-scale/triangle-graded")->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaRowsSquareGraded)->Name("AreaForm/rows-and-scale/square-graded")->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(Dirichlet)->Name("Cmc/dirichlet")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(Newton)->Name("Cmc/newton")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(Ceres)->Name("Cmc/ceres")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(NLopt)->Name("Cmc/nlopt")->DenseRange(4, 15)->Unit(benchmark::kMicrosecond);
BENCHMARK(AreaNewton)->Name("CmcArea/newton")->DenseRange(4, 10, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(AreaCeres)->Name("CmcArea/ceres")->DenseRange(4, 10, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(AreaNewtonNoTrustRegion)
    ->Name("CmcArea/newton-without-trust-region")
    ->DenseRange(4, 10, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(AreaCeresNoTrustRegion)
    ->Name("CmcArea/ceres-without-trust-region")
    ->DenseRange(4, 10, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(AreaCircle)->Name("CmcArea/circle")->DenseRange(6, 12, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(AreaHelicoid)->Name("CmcArea/helicoid")->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(AreaHelicoidNoTrustRegion)->Name("CmcArea/helicoid-without-trust-region")->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(AreaFolded)->Name("CmcArea/folded")->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(MeanCurvatureCircle)
    ->Name("CmcMeanCurvature/newton/circle")
    ->DenseRange(10, 14, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(MeanCurvatureCirclePlain)
    ->Name("CmcMeanCurvature/newton-plain/circle")
    ->DenseRange(10, 14, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(MeanCurvatureCircleCeres)
    ->Name("CmcMeanCurvature/ceres/circle")
    ->DenseRange(10, 14, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(MeanCurvatureCircleVolume)
    ->Name("CmcMeanCurvature/newton-volume/circle")
    ->DenseRange(10, 12, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(MeanCurvatureCircleVolumeCeres)
    ->Name("CmcMeanCurvature/ceres-volume/circle")
    ->DenseRange(10, 12, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(DegreeArea)->Name("Degree/area")->DenseRange(6, 16)->Unit(benchmark::kMillisecond);
BENCHMARK(DegreeAreaPass)->Name("Degree/area-gradient")->DenseRange(6, 16)->Unit(benchmark::kMicrosecond);
BENCHMARK(DegreeAreaHessian)->Name("Degree/area-hessian")->DenseRange(6, 16)->Unit(benchmark::kMicrosecond);
BENCHMARK(DegreeDh)->Name("Degree/dh")->DenseRange(6, 16)->Unit(benchmark::kMillisecond);
BENCHMARK(DegreeDhFactor)->Name("Degree/dh-factor")->DenseRange(6, 16)->Unit(benchmark::kMicrosecond);
