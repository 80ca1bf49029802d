#pragma once
// The two minimisers of the least-squares mean-curvature functional Φ = Σ r_q²
// (mean_curvature_least_squares.h) behind the cmc solve (cmc_mean_curvature.cpp): solver "newton"
// is the library's own Levenberg–Marquardt loop (minimise_newton), solver "ceres" is
// ceres::Solve with one residual block per quadrature node (minimise_ceres,
// mean_curvature_ceres.cpp). Both start from P, change only the rows `free`, stop at the same
// tests (LsStop, levenberg_marquardt.h) and report the same progress stage; measured side by side by the benchmark
// CmcMeanCurvature/{newton,ceres}/circle/<n> (docs/performance.md).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/levenberg_marquardt.h"
#include "bezierpde/solvers/cmc/mean_curvature_least_squares.h"

namespace bpde::cmc_detail {

/// Levenberg–Marquardt on Φ(P) over the rows `free` of P (in place) until √Φ <= target, a stall, no
/// step, or max_iterations, with geodesic acceleration when `geodesic` (cmc_mean_curvature.cpp).
LsOutcome minimise_newton(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free,
                          double H, double target, int max_iterations, bool geodesic, const ProgressFn& progress);
/// The same problem by ceres::Solve (mean_curvature_ceres.cpp).
LsOutcome minimise_ceres(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free,
                         double H, double target, int max_iterations, const ProgressFn& progress);

}  // namespace bpde::cmc_detail
