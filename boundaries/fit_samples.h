#pragma once
// The Bézier curve of degree n closest to samples whose parameters are not known: the orthogonal
// (geometric) least-squares fit
//
//   min over P_1..P_{n-1} and t_1..t_{M-1} of  Σ_k |x(t_k) − q_k|²,   x(t) = Σ_i B_i^n(t) P_i,
//
// with P_0 = q_0, P_n = q_M and t_0 = 0, t_M = 1 fixed. It is the parameter correction of curve
// fitting (Hoschek, "Intrinsic parametrization for approximation", Computer Aided Geometric Design
// 5 (1988) 27–31: each t_k moves to the foot point of q_k on the fitted curve, then the fit is
// repeated), solved as one nonlinear least-squares problem, because the alternation converges
// slowly (docs/boundaries.md, "Samples without parameters").
//
// Method (fit_samples.cpp):
//   - Levenberg–Marquardt on the residuals x(t_k) − q_k with exact Jacobians (x'(t_k) for t_k,
//     B_i^n(t_k) Id for P_i), the t_k eliminated by the Schur complement (each residual has its own
//     t_k: the reduced system has 3(n − 1) unknowns, assembled by one rank-update per iteration).
//     A step is kept only where the parameters still increase strictly inside [0, 1] and the sum
//     of squares falls; at most 100 iterations per degree.
//   - A degree ladder: degree 3 from t0, each degree's parameters the start of the next, up to n.
//     From t0 at degree n directly the iteration crawls along the nearly free parametrisation.
//   - Cost: O(iterations · samples · n²); with more than 2049 samples the ladder runs on 2049 of
//     them (evenly spread by index, the ends included), the other parameters are interpolated
//     linearly in the index between theirs, and 20 iterations over all samples finish.
//   The result is kept (`corrected`) only when its sum of squares is below that of the least
//   squares at t0; otherwise that fit is returned.
//   Hand-written rather than Ceres: bpde_core (nets, boundary curves) links Eigen alone, so that a
//   program that uses only the nets does not link Ceres (CMakeLists.txt, tests/package).
//
// Conditioning: the least squares at given parameters (least_squares_at) solve the Bernstein
// system by a complete orthogonal decomposition at a rank relative to rounding, not a fixed
// threshold: the Bernstein matrix's condition grows about 2^n, so at degree 50 and above (up to
// the nets' 64) its smallest singular values fall below 1e-12 of the largest although n − 1
// distinct inner parameters determine the fit exactly; the dropped directions move the fitted
// values by rounding only (a helix sampled 1000 or 100000 times is fitted to 1e-13 at n = 64).
//
// Shapes: q is (M+1) x 3 (M >= 1), t0 has M+1 entries, strictly increasing from 0 to 1.
// Conventions: Bernstein coefficients P are (n+1) x 3, P_0 first (core/bernstein.h).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <functional>

namespace bpde {

struct SampleFit {
  Eigen::MatrixX3d points;  ///< (n+1) x 3 Bernstein coefficients
  Eigen::VectorXd params;   ///< the parameters of the samples on the fit (M+1)
  bool corrected = false;   ///< the joint problem's result was kept
  int iterations = 0;       ///< Levenberg–Marquardt iterations taken
};

/// Least squares at degree n over the samples q at the parameters t, the end points fixed to q's
/// first and last rows. SizeError when there are fewer than n+1 samples, ParameterError when the
/// parameters do not determine the fit (too few distinct ones inside (0,1)).
Eigen::MatrixX3d least_squares_at(int n, const Eigen::VectorXd& t, const Eigen::MatrixX3d& q);

/// The orthogonal least-squares fit above, from the parameters t0. Throws as least_squares_at.
SampleFit fit_samples_orthogonal(int n, const Eigen::VectorXd& t0, const Eigen::MatrixX3d& q);

/// The iterations of fit_samples_orthogonal_constrained.
struct ConstrainedFitOptions {
  /// Levenberg–Marquardt iterations, >= 1 (with more than 2049 samples at most 20).
  int max_iterations = 100;
  /// The first damping relative to the largest diagonal entry of the normal equations, > 0. Small
  /// where P is already near the optimum in the stiff directions and only the nearly free
  /// reparametrisations are left (a curve's rows in fit_boundary.h: 1e-12).
  double initial_damping = 1e-3;
  /// Where set, a step is kept only where it returns true for the step's points ((n+1) x 3).
  std::function<bool(const Eigen::MatrixX3d&)> admissible;
};

/// The same problem with the inner points constrained to P_inner = P_inner(start) + G z (G is
/// 3(n−1) x N, rows point-major: 3(i−1)+c for P_i's coordinate c), from the fit P (degree n >= 2,
/// already in the constrained set) at the parameters t: Levenberg–Marquardt over z and the
/// parameters, as above. Used for the G¹ corners of fit_boundary.h (the end legs along given
/// directions). SizeError when the sizes do not match, NonFiniteError for non-finite input,
/// ParameterError unless t increases strictly from 0 to 1, or for invalid options.
SampleFit fit_samples_orthogonal_constrained(const Eigen::MatrixX3d& P, const Eigen::VectorXd& t,
                                             const Eigen::MatrixX3d& q, const Eigen::MatrixXd& G,
                                             const ConstrainedFitOptions& options = {});

}  // namespace bpde
