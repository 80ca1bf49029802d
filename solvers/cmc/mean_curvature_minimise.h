#pragma once
// The two minimisers of the least-squares mean-curvature functional Φ = Σ r_q²
// (mean_curvature_least_squares.h) behind the cmc solve (cmc_mean_curvature.cpp): solver "newton"
// is the library's own Levenberg–Marquardt loop (minimise_newton), solver "ceres" is
// ceres::Solve with one residual block per quadrature node (minimise_ceres,
// mean_curvature_ceres.cpp). Both start from P, change only the rows `free`, stop at the same
// tests (LsStop) and report the same progress stage; measured side by side by the benchmark
// CmcMeanCurvature/{newton,ceres}/circle/<n> (docs/performance.md).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/mean_curvature_least_squares.h"

namespace bpde::cmc_detail {

/// Why a minimiser stopped.
enum class LsStop {
  Reached,  ///< √Φ <= its target on the rule minimised
  Stalled,  ///< Φ fell by less than 1e-6 (relative) in 10 iterations
  NoStep,   ///< no trial step lowered Φ (newton: 30 tries with growing damping; ceres: its trust region collapsed)
  MaxIterations,  ///< options.max_least_squares_iterations used up
  NonFinite,      ///< Φ or its Jacobian is not finite at the current net
  VolumeUnmet,    ///< V form: the start could not be put on V = v0 (restore_volume failed)
};

struct LsOutcome {
  int iterations = 0;  ///< newton: accepted steps; ceres: steps tried (accepted and rejected)
  LsStop stop = LsStop::MaxIterations;
};

/// The stall test shared by both: Φ of the last 11 accepted iterates, oldest first; stalled when it
/// fell by less than 1e-6 of the oldest over them.
inline bool stalled(const std::vector<double>& last11) {
  return last11.size() == 11 && last11.front() - last11.back() < 1e-6 * last11.front();
}

/// Progress of the stage "cmc least squares": the fraction of the way from the start's √Φ to the
/// target on a log scale, in [0, 0.999] (1 is reported at the end).
inline double ls_fraction(double start, double target, double sqrt_phi) {
  const double span = std::log(start / target), f = span > 0 ? std::log(start / sqrt_phi) / span : 1.0;
  return std::isfinite(f) ? std::clamp(f, 0.0, 0.999) : 0.0;
}

/// Levenberg–Marquardt on Φ(P) over the rows `free` of P (in place) until √Φ <= target, a stall, no
/// step, or max_iterations, with geodesic acceleration when `geodesic` (cmc_mean_curvature.cpp).
LsOutcome minimise_newton(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free,
                          double H, double target, int max_iterations, bool geodesic, const ProgressFn& progress);
/// The same problem by ceres::Solve (mean_curvature_ceres.cpp).
LsOutcome minimise_ceres(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free,
                         double H, double target, int max_iterations, const ProgressFn& progress);

}  // namespace bpde::cmc_detail
