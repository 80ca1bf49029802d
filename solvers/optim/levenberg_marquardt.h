#pragma once
// Levenberg–Marquardt with geodesic acceleration for a small dense least-squares problem
//
//     minimise Φ(x) = ‖r(x)‖²  over x ∈ Rᵏ,   optionally subject to one equation c(x) = 0,
//
// the library's own loop behind the mean-curvature functional's solver `newton`
// (cmc_mean_curvature.cpp: x = the free coordinates, point-major (3a + c), and in the V form H as
// the last unknown; c = V − v0). Here on its own, so that each part is tested on problems with a
// closed-form answer (tests/cmc/test_levenberg_marquardt.cpp).
//
// Method. Each iteration factors M = JᵀJ + λ D once (Cholesky; D = diag JᵀJ, floored at 1e-12 of
// its largest entry, or with options.marquardt_scaling = false D = max diag JᵀJ · Id) and takes the velocity
//     δ = −M⁻¹Jᵀr,   or with the constraint the KKT solution of
//     min ‖r + Jδ‖² + λ δᵀDδ  subject to  ∇cᵀδ = −c:   δ = δ₀ − μ e,  e = M⁻¹∇c,  μ = (∇cᵀδ₀ + c)/(∇cᵀe).
// With geodesic acceleration (Transtrum and Sethna, "Improvements to the Levenberg–Marquardt
// algorithm for nonlinear least-squares minimization", 2012) the second directional derivative of r
// along δ is taken by one more residual evaluation,
//     r_δδ ≈ (2/h) ((r(x + hδ) − r(x))/h − Jδ)          (exact when r is quadratic),
// the acceleration a = −M⁻¹Jᵀr_δδ (with the constraint: projected, a − (∇cᵀa/∇cᵀe) e, so that
// ∇cᵀa = 0) and the trial step is δ + a/2: the second-order Taylor step along the geodesic the LM
// velocity starts. It is taken only when 2‖a‖_D ≤ α‖δ‖_D (α = 0.75; the paper and GSL's `avmax`
// take ‖a‖ ≤ α‖δ‖; this bound is twice as strict, by measurement: docs/cmc_algorithm.md, "The least squares of the mean curvature"); otherwise the trial counts as rejected. With λ = 0 and one residual in one
// unknown the accelerated step is Chebyshev's third-order step x − r/r' − r''r²/(2r'³), which the
// tests use as the closed-form check of the factor 1/2.
//
// A trial point is put back on c = 0 by `restore` (with the constraint) and accepted when Φ falls;
// λ is then divided by 5 when the gain ratio (Φ − Φ_trial)/(predicted fall of δ) exceeds 0.75 and
// multiplied by 3 below 0.25; a rejected trial multiplies λ by 10. At most 30 trials per iteration.
//
// Worked example (the test RosenbrockValley): r(x) = (10(x₁ − x₀²), 1 − x₀) from (−1.2, 1) reaches
// √Φ ≤ 1e-10 at (1, 1); plain Levenberg–Marquardt follows the curved valley in short steps, the
// accelerated loop in fewer.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "bezierpde/core/progress.h"

namespace bpde::optim {

/// Why a minimiser stopped (shared by this loop and the Ceres route of the mean-curvature functional).
enum class LsStop {
  Reached,  ///< √Φ <= its target
  Stalled,  ///< Φ fell by less than 1e-6 (relative) in 10 iterations
  NoStep,   ///< no trial step lowered Φ (newton: 30 tries with growing damping; ceres: its trust region collapsed)
  MaxIterations,    ///< the iteration limit used up
  NonFinite,        ///< Φ or its Jacobian is not finite at the current point
  ConstraintUnmet,  ///< with a constraint: the start could not be put on c = 0 (`restore` failed)
  Interrupted,      ///< the problem's monitor stopped it (the mean-curvature route: the rule no longer resolves Φ)
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

/// Progress fraction: the way from the start's √Φ to the target on a log scale, in [0, 0.999] (1 is
/// reported at the end).
inline double ls_fraction(double start, double target, double sqrt_phi) {
  const double span = std::log(start / target), f = span > 0 ? std::log(start / sqrt_phi) / span : 1.0;
  return std::isfinite(f) ? std::clamp(f, 0.0, 0.999) : 0.0;
}

/// The problem: k unknowns, r(x) with its Jacobian, and optionally one equation c(x) = 0.
struct LeastSquaresProblem {
  /// r(x) (#r) and, when J is not null, its Jacobian (#r by k). Must accept any finite x.
  std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J)> residuals;
  /// Empty: unconstrained. Otherwise c(x) and, when grad is not null, ∇c(x) (k).
  std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd* grad)> constraint;
  /// With a constraint: moves x onto c = 0 in place; false when it cannot (x is then unspecified).
  std::function<bool(Eigen::VectorXd& x)> restore;
  /// Optional: called at the start (iterations = 0, after the restoration onto c = 0) and after
  /// every accepted step, with the point, the accepted steps so far and Φ there; false stops the
  /// loop (LsStop::Interrupted, x that point).
  std::function<bool(const Eigen::VectorXd& x, int iterations, double phi)> monitor;
};

struct LevenbergMarquardtOptions {
  double target = 0.0;                ///< stop when √Φ <= target; default 0 (never), >= 0
  int max_iterations = 2000;          ///< accepted steps at most; default 2000, >= 0
  bool geodesic_acceleration = true;  ///< the step δ + a/2 (Transtrum–Sethna); default true
  double initial_lambda = 1e-3;       ///< λ of the first trial; default 1e-3, >= 0 and finite
  double geodesic_h = 0.1;            ///< finite-difference step of r_δδ, relative to δ; default 0.1, in (0, 1]
  double geodesic_alpha = 0.75;       ///< taken when 2‖a‖_D <= α‖δ‖_D; default 0.75, > 0
  /// D = diag JᵀJ (Marquardt's scaling, true) or D = max diag JᵀJ · Id (Levenberg's, false: the
  /// damping a trust region in the Euclidean norm of x, which the area soft-mode phase takes, its
  /// x being C-orthonormal coordinates); default true.
  bool marquardt_scaling = true;
  std::string stage = "least squares";  ///< progress stage name; default "least squares"
  /// Throws ParameterError naming the first option out of range.
  void validate() const;
};

/// The velocity and acceleration of one trial at a given λ (exposed for the tests; the loop uses
/// the same arithmetic). `ok` is false when M is not positive definite or a solve is not finite.
struct LmTrial {
  bool ok = false;
  Eigen::VectorXd velocity;      ///< δ
  Eigen::VectorXd acceleration;  ///< a (empty without geodesic acceleration)
  double bend = 0.0;             ///< 2‖a‖_D / ‖δ‖_D (0 without geodesic acceleration)
  bool bent = false;             ///< bend > α: the trial is rejected (the step bends too much for its model)
};

/// r_δδ ≈ (2/h)((r(x + hδ) − r(x))/h − Jδ): the second directional derivative of r along δ by one
/// more residual r_h = r(x + hδ); exact when r is quadratic in x.
Eigen::VectorXd second_directional_derivative(const Eigen::VectorXd& r, const Eigen::VectorXd& r_h,
                                              const Eigen::MatrixXd& J, const Eigen::VectorXd& delta, double h);

/// One trial at x (r, J its residuals and Jacobian) and damping λ, as the loop takes it. Throws
/// ParameterError (options, λ < 0, a missing callback) and SizeError (sizes that do not match).
LmTrial levenberg_marquardt_trial(const LeastSquaresProblem& problem, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& r, const Eigen::MatrixXd& J, double lambda,
                                  const LevenbergMarquardtOptions& options);

/// Minimises Φ from x (in place; with a constraint x is first restored onto c = 0, on a copy: if
/// that fails x is left as given and the stop is ConstraintUnmet). Stops at √Φ <= target, a stall,
/// no step, max_iterations or a non-finite Φ; x is the last accepted point. Progress: options.stage
/// with ls_fraction after every iteration, 0 at the start and 1 at the end. Throws ParameterError
/// for invalid options or a missing callback (residuals; restore with a constraint), SizeError for
/// no unknowns, a J without x.size() columns, residuals that change size or a constraint gradient
/// of the wrong size, and NonFiniteError for a start x that is not finite.
LsOutcome levenberg_marquardt(const LeastSquaresProblem& problem, Eigen::VectorXd& x,
                              const LevenbergMarquardtOptions& options, const ProgressFn& progress = {});

}  // namespace bpde::optim
