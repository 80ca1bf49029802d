#pragma once
// The typed record of an area solve (CmcOptions::functional = Area): which routes the driver
// considered, in its order, how each ended, which one the result comes from and why
// (docs/cmc_algorithm.md describes the routes and the final phases under the same names).
//
// Conventions: first variations are relative (the residual of CmcFunctional / AreaForm: max over
// the free rows of |∇F| over the size of its terms); a route that failed has none.
#include <optional>
#include <string>
#include <vector>

#include "bezierpde/solvers/summary.h"

namespace bpde {

/// The routes of the area solve, in the order the driver may try them.
enum class AreaRoute {
  MeanCurvatureStart,    ///< the least-squares mean-curvature surface, corrected on A_H (both forms)
  DirichletStart,        ///< H form: the D_H critical point, through the vanishing Dirichlet regulariser
  HContinuation,         ///< H form: continuation in H on A_H from the minimal surface (H = 0)
  DirichletVolumeStart,  ///< V form: the minimiser of D at V = V0, through the regulariser at fixed V0
  SmallerVolumeStart,    ///< V form: the same at a smaller volume V1, then continued in V to V0
  VContinuation,         ///< V form: continuation in V from the minimal surface
  MinimalSurface,        ///< H = 0: the corrector on A from the Dirichlet extremal
};
/// "mean-curvature-start", "dirichlet-start", "h-continuation", "dirichlet-volume-start",
/// "smaller-volume-start", "v-continuation", "minimal-surface".
const char* to_string(AreaRoute r);

/// The final phases on A_H (ε = 0) that a route may end with.
enum class AreaPhase {
  RuleRefresh,      ///< the quadrature rule chosen again at the net reached (count: times it changed)
  TruncatedNewton,  ///< Newton on the well-conditioned modes of the Hessian
  SoftModeLm,       ///< the soft-mode phase by Levenberg–Marquardt (solver newton)
  SoftModeCeres,    ///< the soft-mode phase by Ceres (solver ceres)
  TrustRegion,      ///< trust-region Newton steps on A_H inside the soft-mode phase
};
/// "rule-refresh", "truncated-newton", "soft-mode-lm", "soft-mode-ceres", "trust-region".
const char* to_string(AreaPhase p);

/// How the last soft-mode phase of a route ended, where that end is the net the route left.
enum class SoftModeEnd {
  None,             ///< not at such an end
  Stationary,       ///< no step over the soft modes lowers the first variation (a stationary point of its norm)
  DegenerateBound,  ///< the trust-region descent heads for a degenerate parametrisation; the net is its start
};
/// "none", "stationary", "degenerate-bound".
const char* to_string(SoftModeEnd e);

struct AreaPhaseRecord {
  AreaPhase phase = AreaPhase::TruncatedNewton;
  int count = 0;  ///< iterations (RuleRefresh: rule changes)
};

struct AreaRouteRecord {
  AreaRoute route = AreaRoute::DirichletStart;
  /// false: skipped by its gate (`why` says why). Routes not needed (an earlier one converged)
  /// have no record.
  bool tried = false;
  /// How the route itself ended: Converged (first variation within the tolerance), NumericalLimit
  /// (a point above it), or why it failed (NoConvergence, Fold).
  Status status = Status::NoConvergence;
  /// The relative first variation where the route ended (the V form: with the volume's deviation);
  /// on a checked quadrature rule where the driver compared it with another route's. None: failed.
  std::optional<double> first_variation;
  /// mean-curvature-start: √Φ of its least squares, and whether they met their tolerance.
  std::optional<double> least_squares_residual;
  bool least_squares_converged = false;
  /// smaller-volume-start: the volume V1 the continuation started from.
  std::optional<double> start_volume;
  int iterations = 0;          ///< corrector and final-phase iterations inside the route
  int continuation_steps = 0;  ///< accepted continuation steps (h-, v-continuation, smaller-volume-start)
  double seconds = 0.0;
  std::vector<AreaPhaseRecord> phases;  ///< final phases run inside the route, in the order first met
  SoftModeEnd soft_mode_end = SoftModeEnd::None;
  bool kept = false;    ///< the result comes from this route
  std::string message;  ///< the route's own account of how it ended
  std::string why;      ///< why it was kept, not kept, or not tried

  /// Iterations of `phase` in this route (0 when it did not run).
  int phase_count(AreaPhase phase) const;
  /// Add `count` to `phase` (a new entry the first time).
  void add_phase(AreaPhase phase, int count);
};

struct AreaRouteLog {
  std::vector<AreaRouteRecord> records;  ///< in the order the driver considered them
  /// The route whose end the result reports: the kept one, or where every route failed the one
  /// whose failure is reported (the last tried). None: no route ran.
  std::optional<AreaRoute> reported;

  /// The record of `route` (null: not considered).
  const AreaRouteRecord* find(AreaRoute route) const;
  AreaRouteRecord* find(AreaRoute route);
  /// The record the result comes from (null: none kept, the solve failed in every route).
  const AreaRouteRecord* kept() const;
  AreaRouteRecord* kept();
  /// Iterations of `phase` over all routes.
  int phase_count(AreaPhase phase) const;
};

/// One line per considered route: route, tried or not, status, first variation, iterations,
/// steps, seconds, phases, kept and why (compare ceres::Solver::Summary::FullReport()).
std::string full_report(const AreaRouteLog& log);
/// One line: the kept route and its status, or that none was kept.
std::string brief_report(const AreaRouteLog& log);
/// The parenthesised notes the summary message ends with: each route tried and not reported
/// (" (<route>: <message>)"), each gate that skipped one (" (<route> not tried: <why>)") and why
/// the kept one was preferred to another (" (kept: <why>)").
std::string route_notes(const AreaRouteLog& log);

}  // namespace bpde
