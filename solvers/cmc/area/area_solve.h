#pragma once
// Internal to solvers/cmc/area/: the state of one area solve (the net, the quadrature rule, the
// damping, the regulariser) and the steps its routes share. Each route is a member defined in its
// own route_*.cpp, the shared steps in area_solve.cpp (rules, saved states, residuals),
// regulariser_path.cpp (the vanishing Dirichlet regulariser), final_phases.cpp,
// bordered_corrector.cpp and rule_check.cpp; driver.cpp runs the routes in the order
// routes_for() gives. docs/cmc_algorithm.md explains the method under the same names.
//
// Conventions: H is the mean curvature of the result (CmcOptions); "residual" and "first
// variation" are relative (AreaProblem::residual_at); the V form's residual also holds
// |V − V0| over the volume's scale (vresidual). Members are explicitly instantiated for
// TriangularNet, TensorNet and ComplexNet (a surface of several patches, complex_net.h) in the
// file that defines them.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "bezierpde/energies/area_rule.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/area/tuning.h"
#include "bezierpde/solvers/cmc/area_route.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/complex_net.h"
#include "bezierpde/solvers/summary.h"

namespace bpde::cmc_detail::area_impl {

inline bool is_triangular(const TriangularNet&) { return true; }
inline bool is_triangular(const TensorNet&) { return false; }
inline bool is_triangular(const ComplexNet& c) { return c.triangular(); }
/// Whether mean-curvature-start runs: on a complex up to kMeanCurvatureStartCoordinates free
/// coordinates (tuning.h: the least squares' loop is dense and costs minutes above it).
inline bool has_mean_curvature_start(const TriangularNet&) { return true; }
inline bool has_mean_curvature_start(const TensorNet&) { return true; }
inline bool has_mean_curvature_start(const ComplexNet& c) {
  return 3 * static_cast<long long>(c.free_indices(FixedSet::Boundary).size()) <= kMeanCurvatureStartCoordinates;
}

/// How a route ended: H reached, whether it produced a point (ok; possibly above the tolerance,
/// a numerical limit), why not, and its own words.
struct AreaOutcome {
  double H = 0.0;
  bool ok = false;
  Status why = Status::NoConvergence;
  std::string message;
};

/// One stage of the vanishing regulariser at ε: corrects p (and, in the V form, H) and says
/// whether it met the stage tolerance.
using StageFn = std::function<bool(double& H, double eps)>;

template <class Net>
struct AreaSolve {
  /// The solve of `data` with options o from the problem p (its rule unset), its iterations
  /// counted into `summary`.
  AreaSolve(const Net& data_, const CmcOptions& o_, AreaProblem p_, Summary& summary_)
      : data(data_), o(o_), p(std::move(p_)), tri(is_triangular(data_)), n(data_.n()), m(data_.n()), summary(summary_) {
    if constexpr (std::is_same_v<Net, TensorNet>) m = data_.m();
  }

  const Net& data;
  const CmcOptions& o;
  AreaProblem p;
  bool tri;
  int n, m;  ///< the degrees (triangular: n, n)
  double theta = 1.0;  ///< the damping carried from one corrector call to the next
  Summary& summary;
  /// The record of the route running (finish() adds its phases); null between routes.
  AreaRouteRecord* record = nullptr;

  // ---- area_solve.cpp: rules, states and residuals

  /// The D_H critical point at H (with V0: the minimiser of D at V = V0 by nlopt), solved once
  /// for the last (H, V0) asked: the gate of mean-curvature-start, its least squares and the
  /// Dirichlet starts share it (the nlopt minimiser costs up to 0.17 s at n = 12).
  const CmcResult<Net>& dirichlet_solution(double H, const double* V0);
  std::optional<std::pair<std::pair<double, std::optional<double>>, CmcResult<Net>>> dirichlet_cache;

  /// The rule chosen at the current net for a corrector run to `tol` (rule tolerance
  /// kRuleToleranceFactor × tol), from the given start (0: the coarsest). Each ε-stage chooses its
  /// own, the jump to ε = 0 the full one. True when it meets its tolerance.
  bool choose_rule_for(double tol, int start_q = 0, int start_grading = 1, int start_levels = 0);
  bool choose_rule(int start_q = 0, int start_grading = 1, int start_levels = 0) {
    return choose_rule_for(o.tolerance, start_q, start_grading, start_levels);
  }
  /// The rule checked at the current net and refined from the rule in use (never coarser).
  bool refine_rule();
  double rule_change = 0.0;  ///< the measured error of the rule last chosen

  /// Where the last final phases ended at a soft-mode end (SoftModeEnd): the net and the rule
  /// there, so that the end is recognised while the net reported is still that point on that rule
  /// (at ε = 0). H form only (the V form's end goes on back onto V0).
  struct SoftEndMark {
    SoftModeEnd kind = SoftModeEnd::None;
    Eigen::MatrixX3d P;
    std::shared_ptr<const AreaForm> a;
  };
  SoftEndMark stationary_end, degenerate_end;
  /// Whether p is still at `mark`.
  bool at(const SoftEndMark& mark) const;
  /// The soft-mode end p is at (None when it has moved on since).
  SoftModeEnd soft_end() const;
  /// The words for such an end: "" otherwise.
  std::string soft_verdict(bool long_form) const;

  /// What a route changes: the net, the rule and its error, the damping, ε and the soft-mode
  /// marks. A route tried and not kept puts them back.
  struct State {
    Eigen::MatrixX3d P;
    std::shared_ptr<const AreaForm> a;
    double theta = 1.0, rule_change = 0.0, eps = 0.0;
    SoftEndMark stationary_end, degenerate_end;
  };
  State save() const;
  void restore(const State& s);

  /// A mean-curvature-start end above the tolerance but within kAreaStallResidual at a regular net
  /// whose rule met its tolerance: kept aside for the driver to compare with the other routes'.
  struct RouteEnd {
    State state;
    std::string note;
  };
  std::optional<RouteEnd> stalled_mean_curvature_end;

  /// The residual at H with a rule refined until it meets its tolerance at the current net (the
  /// rule in use is put back); +inf when not finite. The driver compares routes by it.
  double checked_residual(double H);
  /// The V form's residual at ε = 0.
  double vresidual(double V0, double H) const;
  /// A strict local minimum of A_H before the fold: K + σC positive definite (kStrictMinimumShift);
  /// the tangent of the branch −2 (K + σC)⁻¹ ∇V into `tangent` when given.
  bool strict_minimum(double H, Eigen::VectorXd* tangent);
  /// The gate of mean-curvature-start: the relative first variation of A_H at the D_H critical
  /// point (V form: at the minimiser of D at V0, with its multiplier); +inf where it does not exist.
  double dirichlet_first_variation(const double* V0);

  // ---- final_phases.cpp

  /// Whether finish() may choose the rule again (off in the final rule check, which only refines).
  bool choose_rules_again = true;
  /// The final phases at ε = 0: newton, the truncated Newton phase, which ends in the soft-mode
  /// phase; ceres, the soft-mode phase by Ceres alone. Records them in `record`.
  CorrectorStats finish(double H, int max_iterations);
  /// "the truncated Newton phase [in N iteration(s)] and the soft-mode phase [in M]".
  static std::string final_phases(const CorrectorStats& t, bool counts);
  /// The corrector to max(tol, tolerance), then where it stalls at ε = 0 the final phases.
  CorrectorStats correct(double H, double tol);
  /// The V form's end at ε = 0 above the tolerance: the final phases at H, then bordered
  /// iterations back onto V0; kept when the V form's residual falls ("; finished by …", else "").
  std::string finish_volume(double V0, double& H);
  /// The critical point of A (H = 0) from the net in p, to `tol`.
  bool minimal_surface(double tol);

  // ---- regulariser_path.cpp

  /// The vanishing Dirichlet regulariser from a critical point of F_1 = D_H in p: F_ε for
  /// ε = 1, 1/10, … → 0, each stage by `stage` from the Euler predictor, with the jump to ε = 0
  /// from kJumpFromEpsilon on. With V0: stages at fixed V, H moves.
  bool homotopy(double& H, const StageFn& stage, std::string& note, const double* V0 = nullptr);
  /// The jump to ε = 0: predictor, then kJumpIterations corrector iterations on A_H; kept when
  /// they converge, else everything goes back.
  bool jump(double& H, double eps, const double* V0 = nullptr);
  /// The Euler predictor along the ε-path from ε = eps to `next` (bordered with fixed_volume).
  void predict(double& H, double eps, double next, bool fixed_volume = false);
  /// The stage tolerance at ε.
  CmcOptions stage_options(double e) const;

  // ---- bordered_corrector.cpp

  /// The V form's corrector: bordered regularised Newton on (Y, H) for ∇F_ε + 2H∇V = 0, V = V0,
  /// to `tol` (default: the tolerance) in at most max_iterations (default 2 max_corrector_iterations).
  CorrectorStats bordered_correct(double V0, double& H, double tol = -1.0, int max_iterations = -1);

  // ---- the routes (route_*.cpp), in driver order

  /// mean-curvature-start (both forms). On failure everything goes back; `note` says how it ended.
  bool from_mean_curvature(const double* V0, double& H, std::string& note, int& steps);
  /// dirichlet-start: the D_H critical point at H, corrected on A_H.
  bool from_dirichlet(double H, std::string& note);
  /// h-continuation: continuation in H on A_H from the critical point of A at H = 0.
  AreaOutcome continuation(const Eigen::MatrixX3d& start, const std::vector<int>& fixed_idx, int& steps);
  /// dirichlet-volume-start: the minimiser of D at V = V0, through the regulariser at fixed V0.
  AreaOutcome from_dirichlet_volume(double V0);
  /// smaller-volume-start: dirichlet-volume-start at V1 between Vref and V0, continued in V.
  AreaOutcome volume_continuation_from_smaller(double V0, double Vref, int& steps);
  /// v-continuation: continuation in V from the critical point of A at H = 0.
  AreaOutcome volume_continuation(const Eigen::MatrixX3d& start, int& steps);
  /// Continuation in V along the volume-constrained critical points of A from the one in p.
  AreaOutcome continue_volume(double Vs, double H, double V0, int& steps, double step_tol, bool fresh_damping);
  /// minimal-surface (H = 0): the corrector on A from the net in p.
  AreaOutcome minimal_surface_route();

  // ---- rule_check.cpp

  /// The final rule check on an ok outcome: refine while the rule misses its tolerance at the
  /// final net, and correct again with the finer rule; a rule that still misses, or a correction
  /// that stalls, makes the outcome a numerical limit.
  void rule_check(AreaOutcome& out);
};

}  // namespace bpde::cmc_detail::area_impl
