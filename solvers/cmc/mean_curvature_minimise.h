#pragma once
// The two minimisers of the least-squares mean-curvature functional Φ = Σ r_q²
// (mean_curvature_least_squares.h) behind the cmc solve (cmc_mean_curvature.cpp): solver "newton"
// is the library's own Levenberg–Marquardt loop (minimise_newton), solver "ceres" is
// ceres::Solve with one residual block per quadrature node (minimise_ceres,
// mean_curvature_ceres.cpp). Both start from P, change only the rows `free`, stop at the same
// tests (LsStop, levenberg_marquardt.h) and report the same progress stage; measured side by side by the benchmark
// CmcMeanCurvature/{newton,ceres}/circle/<n> (docs/performance.md).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/solvers/optim/levenberg_marquardt.h"
#include "bezierpde/energies/mean_curvature_least_squares.h"

namespace bpde::cmc_detail {
using namespace bpde::optim;  // the generic least squares and trust-region steps (solvers/optim)

/// The volume constraint of the V form: V(P) = V0, with H an unknown.
struct VolumeTarget {
  const VolumeForm& form;
  double V0;
  double scale;  ///< > 0, the volume's scale at the start: |V − V0| <= 1e-14 × scale is "on the constraint"
};

/// Back onto V = V0 along the volume gradient over the rows `free` of P (in place): at most 8 Newton
/// steps on the one equation (V is cubic in P). False when it does not get there
/// (cmc_mean_curvature.cpp).
bool restore_volume(const VolumeTarget& vt, Eigen::MatrixX3d& P, const std::vector<int>& free);

/// The check of the rule minimised, every kRuleCheckEvery accepted steps of either minimiser: √Φ by
/// the finer rule `check` at P (with H) against √phi of the rule minimised. They agree when the
/// check reads at most kRuleAgreement × √phi, or at most the target. Measured on the conformal
/// sphere triangle at n = 10 (docs/cmc_algorithm.md, "The area functional A_H"): with q = 9 the
/// iterate folds after 200–400 steps where the q = 60 rule reads 5.6e-2 against 6e-6; the coarse
/// rule's own value disagreed with q = 60 by ×1.4 at step 100 and ×1.2 at step 200 before that.
inline constexpr int kRuleCheckEvery = 10;
inline constexpr double kRuleAgreement = 2.0;
inline constexpr int kMaxRuleRefinements = 2;
inline bool rules_agree(const MeanCurvatureLeastSquares& check, const Eigen::MatrixX3d& P, double H, double phi,
                        double target) {
  const double c = std::sqrt(check.value(P, H));
  return c <= std::max(kRuleAgreement * std::sqrt(phi), target);
}

/// Levenberg–Marquardt on Φ(P) over the rows `free` of P (in place) until √Φ <= target, a stall, no
/// step, or max_iterations, with geodesic acceleration when `geodesic`; with check, it stops
/// (LsStop::Interrupted, P at the last agreed point) when rules_agree fails (cmc_mean_curvature.cpp).
LsOutcome minimise_newton(const MeanCurvatureLeastSquares& f, const MeanCurvatureLeastSquares* check,
                          Eigen::MatrixX3d& P, const std::vector<int>& free, double H, double target,
                          int max_iterations, bool geodesic, const ProgressFn& progress);
/// The same problem by ceres::Solve (mean_curvature_ceres.cpp). With vt (the V form) H is an unknown
/// too (in and out) and the free points move on the manifold V = V0 (a ceres::Manifold: steps in the
/// tangent space of ∇V⊥, each trial point put back by restore_volume); the start is put on it first,
/// on a copy (ConstraintUnmet, P and H as given, when that fails).
LsOutcome minimise_ceres(const MeanCurvatureLeastSquares& f, const MeanCurvatureLeastSquares* check,
                         Eigen::MatrixX3d& P, const std::vector<int>& free, double& H, const VolumeTarget* vt,
                         double target, int max_iterations, const ProgressFn& progress);

}  // namespace bpde::cmc_detail
