#pragma once
// The tuning constants of the area solve (solvers/cmc/area/), each with its value, why it is that
// value and where it was measured (docs/cmc_measurements.md unless said otherwise). Internal.
#include <array>
#include <cstddef>

#include "bezierpde/solvers/optim/damping.h"

namespace bpde::cmc_detail::area_impl {

// ---------------------------------------------------------------- routes and their gates

/// mean-curvature-start: least-squares iterations in the H form (the V form takes
/// max_least_squares_iterations: past the hemisphere its continuation in V takes 800–1100).
/// Tensor catenoid n = 12: √Φ 2.3e-6 after 300, and the Newton iterations and final phases converge
/// from there in 3.2 s where 1200 iterations took 10.8 s.
inline constexpr int kMeanCurvatureStartIterations = 300;
/// mean-curvature-start: Newton iterations on A_H from the least squares before the final phases
/// (the circle, n = 8 … 16: 2–5 are needed where the least squares converge).
inline constexpr int kMeanCurvatureStartCorrector = 8;
/// mean-curvature-start is not tried where the relative first variation of A_H at the D_H
/// critical point is at most this (conformal data: the sphere triangle 8.2e-7 at n = 10 and
/// below from there on; the Fig. 1 circle 7e-2).
inline constexpr double kConformalFirstVariation = 1e-6;
/// A corrector on A that stops above the tolerance but within this relative first variation is a
/// numerical limit (status numerical-limit), not "no critical point"; a mean-curvature-start end
/// within it is kept for comparison with the other routes' ends.
inline constexpr double kAreaStallResidual = 1e-6;
/// Each step of the H and V continuations is corrected to this relative first variation (or the
/// tolerance when looser), the end point then to the tolerance: on the circle at n = 8 steps
/// corrected to 1e-11 stalled at 1.04e-11 from H ≈ −0.9 on, which the step control took for a fold.
inline constexpr double kContinuationStepTolerance = 1e-8;
/// smaller-volume-start: V1 = Vref + (V0 − Vref)/k for these k, the first that works (the circle
/// past the hemisphere; k = 4 first cost 7 s more at n = 10, H = −0.7).
inline constexpr std::array<double, 3> kSmallerVolumeDivisors = {16.0, 64.0, 256.0};
/// The on-branch test of the continuations: the corrected point lies nearer the prediction than
/// this fraction of its distance from the last point, both along the surface normals.
inline constexpr double kBranchGapRatio = 0.5;
/// The positive-definiteness test of the H continuation: K + σC with σ = this × max K_ii/C_ii
/// (the soft-mode phase's split of soft and hard modes; 1e-8 stopped the circle at n = 6 at
/// H = −0.62, 1e-6 the helicoid piece at H ≈ −0.06).
inline constexpr double kStrictMinimumShift = 1e-4;
/// The V continuation's tangent solves (K + this C) against the nearly singular tangential modes.
inline constexpr double kVolumeTangentShift = 1e-8;

// ---------------------------------------------------------------- the vanishing regulariser

/// The first ε ratio (ε = 1, 1/10, …), the smallest (successful stages square it, not below this)
/// and the largest (failed stages take its square root; above this the path gives up).
inline constexpr double kFirstEpsilonRatio = 0.1;
inline constexpr double kSmallestEpsilonRatio = 1e-2;
inline constexpr double kLargestEpsilonRatio = 0.7;
/// Failed stages of the ε-path before it gives up.
inline constexpr int kMaxStageFailures = 12;
/// Below this ε goes to 0 (H form; the V form: kVolumeEpsilonFloor, measured on the circle at
/// n = 6, H = −0.9 and n = 10, H = −0.5, which miss the tolerance with the H form's value).
inline constexpr double kEpsilonFloor = 1e-16;
inline constexpr double kVolumeEpsilonFloor = 1e-12;
/// From this ε on, after each stage, the jump to ε = 0 is tried (the predictor puts the A_H
/// corrector inside its basin, where the stages alone stopped at ε ≈ 1e-8 … 1e-6).
inline constexpr double kJumpFromEpsilon = 1e-4;
/// The jump's corrector: at most this many iterations, from this damping.
inline constexpr int kJumpIterations = 8;
inline constexpr double kJumpDamping = 1e-8;
/// The stage tolerance: max(0.5 tolerance, min(kStageToleranceCap, kStageToleranceFactor ε)),
/// which keeps the A_H residual (≈ ε |∇(D − A)|) on track.
inline constexpr double kStageToleranceCap = 1e-6;
inline constexpr double kStageToleranceFactor = 1e-3;
/// The decades of ε the progress line counts to 1.
inline constexpr double kProgressDecades = 12.0;

// ---------------------------------------------------------------- correctors and final phases

/// The damping a route starts its corrector with (the regularised Newton of every route, and the
/// bordered corrector of the V form's stages and ends).
inline constexpr double kFreshDamping = 1e-3;
/// The bordered iterations that bring the V form back onto V = V0 after the final phases at its H.
inline constexpr int kVolumeReturnIterations = 8;
inline constexpr double kVolumeReturnDamping = 1e-8;
/// The regularised Newton corrector on F_ε (area_newton_correct): 20 factorisations per
/// iteration, θ /4 after ρ > 0.75 (not below 1e-8), ×4 after ρ < 0.25, ×10 after a rejection.
inline constexpr optim::Damping kNewtonDamping{20, 1e-8};
/// The bordered corrector of the V form: 16 factorisations per iteration, θ /4 after a step that
/// lowers the residual (not below 1e-6), ×10 after one that does not.
inline constexpr optim::Damping kBorderedDamping{16, 1e-6};
/// area_newton_correct stops after this many iterations without a fall of the residual.
inline constexpr int kNewtonStallIterations = 4;
/// area_newton_correct: an ε-stage at θ ≥ this whose residual fell less than ×2 over the last
/// kCrawlWindow iterations is a linear crawl along the valley (0.5 % per iteration at θ = 1e6 for
/// up to 60 iterations): the homotopy changes ε instead.
inline constexpr double kCrawlDamping = 1e4;
inline constexpr std::size_t kCrawlWindow = 4;
/// Chord corrections with the same factor after each Newton step (while the residual falls).
inline constexpr int kNewtonChords = 3;
/// The predicted change of A_H below this fraction of its terms is rounding noise: the step is
/// then judged by the fall of the residual.
inline constexpr double kValueNoise = 1e-12;
/// The soft-mode phase's iteration bound, in units of max_corrector_iterations (default 30: 300;
/// the circle at n = 10, H = −0.9 takes 21).
inline constexpr int kSoftModeIterationsPerCorrector = 10;
/// How often (in iterations) the truncated Newton phase asks for the rule to be chosen again.
inline constexpr int kRuleRefreshEvery = 4;
/// The truncated Newton phase: eigenvalue cuts from the first to the last (×0.1 each), the
/// fractions of the dropped (soft) step tried, the chord corrections per trial and the rises of
/// ‖g‖ that end a trial (the second rise: past it the corrections diverge in the soft modes; the
/// circle, sphere patch and tensor catenoid reach the same or lower ends 1.2–2.8× faster).
inline constexpr double kTruncationFirstCut = 1e-5;
inline constexpr double kTruncationLastCut = 1e-10;
inline constexpr std::array<double, 8> kSoftStepFractions = {0.0, 0.003, 0.01, 0.03, 0.1, 0.2, 0.4, 1.0};
inline constexpr int kTruncatedChords = 16;
inline constexpr int kTruncatedChordRises = 2;

// ---------------------------------------------------------------- quadrature rules

/// A rule is chosen for this fraction of the residual tolerance it serves.
inline constexpr double kRuleToleranceFactor = 0.1;
/// The final rule check refines at most this many times.
inline constexpr int kRuleCheckRounds = 4;

/// The final phases decompose dense matrices over all free coordinates (K v = λ C v): on a
/// complex with more free coordinates than this they are not run (their cost, O((3k)³) time and
/// O((3k)²) memory, would be minutes and gigabytes), and a corrector that stalls above the
/// tolerance ends as a numerical limit.
inline constexpr int kDenseFinalPhasesLimit = 3000;

/// Complexes: a converged end is polished by the final phases towards this fraction of the
/// tolerance (not below kComplexPolishFloor), kept where it meets the tolerance still and lowers
/// the first variation. The cap of radius 2 on the fan of 6 at degree 6: the first variation
/// 8.3e-12 leaves the surface 8.3e-8 from the sphere and |H_x − H| up to 2.7e-4; 8.8e-14 puts it
/// 1.9e-9 from the sphere and |H_x − H| below 1.5e-5 (the distance follows the first variation
/// × 1e3 … 1e4).
inline constexpr double kComplexPolishFactor = 1e-2;
inline constexpr double kComplexPolishFloor = 1e-14;
/// The polish runs on complexes of at most this many free coordinates: the fan of 6 up to degree 8
/// and the fan refined once at degree 4 (507 each; 6 s of CPU on top at degree 8). The fan refined
/// twice at degree 3 (1191) took 72 s of CPU with it, 28 s without.
inline constexpr int kComplexPolishCoordinates = 600;

/// mean-curvature-start runs on complexes of at most this many free coordinates (the least squares'
/// Levenberg–Marquardt loop is dense: a #nodes x 3k Jacobian and a 3k x 3k normal matrix per
/// iteration). Measured: the fan of 6 at degree 8 (507) lands 20x nearer the sphere in 5 s; the
/// tensor catenoid ring at degree 8 (672) took 6.9 s instead of 1 s by minimal-surface and ended
/// with a 6x larger certificate; the 4 x 0.5 rectangle at degree 6 (705) spent 75 s before giving
/// way; the fan refined twice at degree 3 (1191) took more than 4 minutes.
inline constexpr int kMeanCurvatureStartCoordinates = 600;

/// A complex with more free coordinates than this is solved with sparse matrices (sparse_terms.h);
/// below, the dense ones of a single patch are as fast (the fan of 6 triangles at n = 8: 507
/// coordinates) and the solve is the single-patch one exactly.
inline constexpr int kSparseFromCoordinates = 1500;

}  // namespace bpde::cmc_detail::area_impl
