#pragma once
// Critical points of the CMC functional D_H = D + 2HV (Arnal, Lluch, Monterde, "Triangular Bézier
// approximations to constant mean curvature surfaces", eq. (11); energies/cmc.h) over the free
// control points of a triangular or tensor net. Orientation and the sign of H: FORMATS.md and
// docs/errata.md, "Conventions".
//
// What is solved (FORMATS.md, problem "cmc"):
//  - H mode (options.V unset): the critical point of D_H on the branch continued from the
//    Dirichlet extremal (H = 0, a linear solve) to the requested H, before the branch's first fold
//    (docs/errata.md, triangular CMC §2: D_H is unbounded below, so this is a critical point, not
//    a minimum). When no branch point exists beyond some H ≈ h (fold: singular Hessian, no
//    convergence), the result has converged = false, message "no critical point on the branch
//    from H = 0 beyond H ≈ <h>", and holds the last point of the branch (at H = h, result.H = h).
//  - V mode (options.V set, solver nlopt only): minimise D subject to V = V0; the multiplier is
//    reported as H = -<∇D,∇V>/(2 |∇V|^2) over the free points, so that ∇D + 2H∇V = 0.
//
// Solvers (one interface, options.solver): newton (exact symmetric Hessian, Cholesky), ceres
// (Levenberg–Marquardt on the residuals F_I of eq. (11)), nlopt (L-BFGS on D_H, polished by at most
// 3 Newton steps). The continuation's step control and each solver's details: docs/cmc_algorithm.md,
// "Solver".
//
// converged = true means eq. (11) over the free points holds to options.tolerance (1e-11) relative
// to the size of its terms (CmcFunctional::residual), and in V mode also |V - V0| <= tolerance *
// (1/3 ∫ |<x_u ∧ x_v, x>|).
//
// The area functional (options.functional = Area): critical points of A_H = A + 2HV,
// A = ∫|x_u ∧ x_v| (energies/area_functional.h), which have mean curvature H whatever the
// parametrisation of the boundary (H = 0: a minimal surface); in the V mode the minimum of A
// subject to V = V0, with its multiplier H. The solve is a sequence of named routes
// (AreaRoute: mean-curvature-start, dirichlet-start, h-continuation, dirichlet-volume-start,
// smaller-volume-start, v-continuation, minimal-surface) ending in named final phases
// (AreaPhase); CmcResult::routes records which ran, how each ended and which one the result comes
// from (area_route.h). docs/cmc_algorithm.md describes the routes and phases under these names,
// solvers/cmc/area/ holds one file per route.
//  - converged = true means the first variation ∇A_H over the free points holds to
//    options.tolerance relative to the size of its terms (the rows of AreaForm's gradient scale
//    plus 2|H| those of V), measured with a quadrature rule whose own measured error is below the
//    tolerance (energies/area_rule.h), AND the parametrisation is regular (CmcResult::
//    parametrisation): |x_u ∧ x_v| on a 40 x 40 sample grid away from the corners (margin 0.05)
//    is at least 1e-3 of its mean, no two neighbouring samples have opposite normals, and no fold
//    lies inside a corner margin. A degenerating surface is reported with converged = false,
//    status NoConvergence and parametrisation.regular = false.
//  - Above the tolerance but within reach of it (a stall in the nearly singular tangential modes)
//    the status is NumericalLimit.
//  - Fixed sets boundary and boundary+adjacent; solvers newton and ceres (V mode too).
//
// The least-squares mean-curvature functional (options.functional = MeanCurvature;
// energies/mean_curvature_least_squares.h; docs/cmc_algorithm.md, "The least squares of the mean curvature"):
//  - H mode: minimise Φ = ∫ ρ (H_x − H)² dA over the free points (ρ a corner weight, 1 away
//    from the corners and 0 at them: mean_curvature_least_squares.h). Φ = 0 exactly for a CMC
//    surface, whatever the parametrisation; where the polynomial space holds no CMC surface, its
//    minimiser is the surface nearest to CMC in that sense (it weighs the deviation on the whole
//    patch, where a critical point of A_H only makes it orthogonal to the B_I, which vanish on the
//    boundary).
//  - V mode (options.V = V0, solvers newton and ceres): minimise Φ over the free points AND H
//    subject to V = V0; result.H is the H found. Solver newton: each Levenberg–Marquardt step
//    solves the LM subproblem with the linearised constraint (KKT, one Cholesky factor), and each
//    trial point is put back on V = V0 along ∇V before Φ is compared (cmc_mean_curvature.cpp,
//    levenberg_marquardt.h). Solver ceres: the free points are a ceres::Manifold, the level set
//    V = V0 (steps in ∇V⊥, trial points put back the same way; mean_curvature_ceres.cpp). Its start is the minimiser of D
//    at V = V0 (the nlopt route) with that route's multiplier as H. converged also needs
//    |V − V0| <= options.tolerance × max(value_scale, |V0|, area^(3/2)) (of the start).
//    When that does not converge (past the hemisphere of a circle the start folds), the V form
//    continues in V: Φ minimised at V1 = V_ref + (V0 − V_ref)/k, k = 4, 16, 64, 256 in turn (V_ref
//    the volume of the Dirichlet extremal), then V stepped to V0 with the H continuation's step
//    control (secant predictor; each step minimised by the same solver and accepted when the rules
//    agree, the parametrisation is regular, V is on its target and √Φ <= max(1e-2, tolerance)).
//    This second route has its own max_least_squares_iterations (a step before V0 at most 200 of
//    them, the step at V0 what is left) and max_continuation_steps step attempts, over all V1. Its
//    end is kept when it is better (converged, or regular and on V0 where the first one was not,
//    or a lower √Φ by the same rule); the message says which route gave the result and how the
//    other ended (docs/cmc_algorithm.md, "The routes", "Past the hemisphere").
//  - The start is the D_H critical point at H (the newton continuation above, whatever the
//    solver; if the branch folds first, its last point). Levenberg–Marquardt on the residuals of Φ with the exact Jacobian:
//    (JᵀJ + λ diag JᵀJ) δ = −Jᵀr, λ by the gain ratio (÷5 above 0.75, ×3 below 0.25, ×10 on a
//    rejected step). Solver newton adds geodesic acceleration (Transtrum and Sethna, "Improvements
//    to the Levenberg–Marquardt algorithm for nonlinear least-squares minimization", 2012;
//    options.geodesic_acceleration): the second directional derivative
//    r_δδ ≈ (2/h)((r(x + hδ) − r(x))/h − Jδ), h = 0.1, gives a = −(JᵀJ + λ diag JᵀJ)⁻¹ Jᵀ r_δδ, and
//    the step is δ + a/2 when 2‖a‖ ≤ 0.75‖δ‖ (norms scaled by diag JᵀJ; twice as strict as the
//    paper's ‖a‖ ≤ 0.75‖δ‖, by measurement), else a rejected step. It follows the curved, nearly
//    tangential valley of Φ that plain LM crawls along (docs/cmc_algorithm.md, "The least squares of the mean curvature": on
//    the circle at n = 8 … 14, 1.6–7.6× fewer iterations where both converge and plain LM needs
//    more than 30, up to 20 % more where it needs about 20).
//  - converged = true means √Φ ≤ options.mean_curvature_tolerance (1e-6; Φ is dimensionless), with
//    Φ measured by a rule finer than the one minimised (q + ⌈q/2⌉ points per direction), AND the
//    regularity test of the area functional. When the rule minimised reaches 0.7 × the tolerance
//    and the check rule does not meet it, or the two disagree by more than 2× on the way (every
//    10 steps), the minimisation goes on with the next finer pair of rules (at most twice). It stops not converged (status NoConvergence, exit 1
//    from the CLI) when Φ stalls (a relative fall below 1e-6 in 10 iterations: the degree is too
//    low for the tolerance) or after options.max_least_squares_iterations; summary.residual is
//    then the √Φ reached.
//  - Fixed sets boundary and boundary+adjacent. Solver newton: the library's own Levenberg–Marquardt
//    loop above (solvers/optim/levenberg_marquardt.h, tested on its own against closed forms). Solver ceres: the same residuals as one Ceres residual block per quadrature node
//    on one parameter block (the free points), minimised by ceres::Solve (LM, dense normal
//    Cholesky) with the same stopping tests (solvers/cmc/mean_curvature_minimise.h); both are
//    measured side by side by CmcMeanCurvature/{newton,ceres}/circle/<n> (docs/performance.md).
//    summary.iterations counts accepted steps (newton) or steps tried, accepted and rejected
//    (ceres); options.max_least_squares_iterations bounds the same counts, per route (the V
//    form's continuation in V is a second route).
//
// Bad input throws: non-finite H or V (NonFiniteError), unknown solver name (ParameterError),
// a fixed set or solver the functional does not take (UnsupportedProblem; cmc_requirements),
// an option out of its range (ParameterError), degree too low for the fixed set
// (DegreeError: triangular n >= 3 with C0 data, n >= 6 with C1 data; tensor n, m >= 2 with C0 data
// and >= 4 with C1 data), u-boundaries on a triangular net (UnsupportedProblem), non-finite data
// points (NonFiniteError).
#include <optional>
#include <string>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/area_route.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

enum class CmcSolver { Newton, Ceres, NLopt };
/// The functional: the paper's D_H = D + 2HV (default; critical points), the geometric
/// A_H = A + 2HV (critical points), or the least squares of the mean-curvature deviation
/// Φ = ∫ (H_x − H)² dA (minimised).
enum class CmcFunctionalKind { Dirichlet, Area, MeanCurvature };

/// "dirichlet" | "area" | "mean-curvature" (ParameterError otherwise).
CmcFunctionalKind parse_cmc_functional(const std::string& name);
std::string to_string(CmcFunctionalKind f);

/// Where the area functional starts (CmcOptions::area_start; docs/cmc_algorithm.md, "The area functional A_H"):
///  - MeanCurvature (default): mean-curvature-start, the least-squares mean-curvature surface, then the routes
///    from the D_H critical point (Dirichlet) and, where they fail, the minimal-surface route;
///  - Dirichlet: the routes from the D_H critical point, then the minimal-surface route;
///  - MinimalSurface: only the branch through the critical point of A at H = 0 (the minimal
///    surface spanning the boundary, from the Dirichlet extremal), continued in H (H form) or in V
///    (V form) to the target. It selects the branch connected to the minimal surface and reports
///    where that branch turns (status Fold in the H form).
enum class AreaStart { MeanCurvature, Dirichlet, MinimalSurface };

/// "mean-curvature" | "dirichlet" | "minimal-surface" (ParameterError otherwise).
AreaStart parse_area_start(const std::string& name);
std::string to_string(AreaStart s);

/// "newton" | "ceres" | "nlopt" (ParameterError otherwise).
CmcSolver parse_cmc_solver(const std::string& name);
std::string to_string(CmcSolver s);

struct CmcOptions {
  double H = 0.0;                            ///< target mean curvature (H mode); default 0
  std::optional<double> V;                   ///< target volume (V mode); default unset
  CmcSolver solver = CmcSolver::Newton;      ///< default newton
  CmcFunctionalKind functional = CmcFunctionalKind::Dirichlet;  ///< default dirichlet
  FixedSet fixed = FixedSet::Boundary;       ///< default boundary (C0 data)
  double tolerance = kConvergenceTolerance;  ///< relative eq. (11) residual; default 1e-11, in (0, 1e-3]
  int max_corrector_iterations = 30;         ///< per continuation step; default 30, >= 1
  int max_continuation_steps = 400;          ///< default 400, >= 1
  double min_step = 1e-5;                    ///< smallest H step, relative to max(1, |H reached|); default 1e-5
  /// mean-curvature functional: converged when √Φ = ‖H_x − H‖ in L²(ρ dA) is at most this; default 1e-6, in (0, 1).
  /// The area functional's mean-curvature-start uses it too, as the least squares' target
  double mean_curvature_tolerance = 1e-6;
  /// mean-curvature functional: Levenberg–Marquardt iterations at most; default 2000, >= 1 (the area
  /// functional's mean-curvature-start: at most min(this, 300) in the H form, this in the V form)
  int max_least_squares_iterations = 2000;
  /// mean-curvature functional, solver newton: geodesic acceleration of the Levenberg–Marquardt
  /// steps (above); default true. false is plain LM, kept to measure the two side by side
  /// (CmcMeanCurvature/{newton,newton-plain}/circle/<n>). Solver ceres has no such step.
  bool geodesic_acceleration = true;
  /// area functional: where it starts (AreaStart above; a job's "start", docs/FORMATS.md); default
  /// MeanCurvature: mean-curvature-start first, the least-squares mean-curvature surface corrected on A_H by a
  /// few Newton iterations (docs/cmc_algorithm.md, "The routes"). Dirichlet starts from the
  /// D_H critical point (dirichlet-start, dirichlet-volume-start), kept to measure the two side by side;
  /// MinimalSurface follows the branch from the minimal surface alone. Other functionals ignore it.
  AreaStart area_start = AreaStart::MeanCurvature;
  /// area functional: where the soft-mode phase's Levenberg–Marquardt loop on the reduced first
  /// variation stops above the tolerance, trust-region Newton on A_H along the valley floor
  /// (docs/cmc_algorithm.md, "The final phases"); default true. false stops
  /// there (the soft-mode phase without its trust-region part), kept to measure the two side by side. Other functionals ignore it.
  bool area_trust_region = true;
  /// Called after each continuation attempt (H mode) with stage "cmc continuation", done = |H
  /// reached|, total = |H requested| (core/progress.h); the mean-curvature functional (and the area
  /// functional's mean-curvature-start) report "cmc least squares", one stage across its rule refinements, the
  /// area functional "cmc area" (the decades of its regulariser removed, out of 12, repeated at
  /// every evaluation of the first variation, so also through the final phases, whose length is
  /// not known; 1 at the end); default none.
  ProgressFn progress;
  /// Throws NonFiniteError (H, V non-finite) or ParameterError (other fields out of range, whatever
  /// the functional), UnsupportedProblem (a fixed set or solver the functional does not take in
  /// this form: cmc_requirements).
  void validate() const;
};

/// Largest degrees of a cmc job: above them the Dirichlet Gram over the free points is no longer
/// Cholesky-factorable (condition ~4^n; docs/cmc.md "Numerical limit"), so eq. (11) cannot be
/// resolved to 1e-11, and the continuation spends minutes (tensor n = 30: 2 min; triangular
/// n = 40: 100 s; n = 64 ran past 5 min and 2.2 GB) before it stops with a numerical limit.
inline constexpr int kMaxCmcTensorDegree = 16;
inline constexpr int kMaxCmcTriangularDegree = 25;

/// The cmc combination rules, stated once: what the FORMATS.md "cmc" problem takes with each
/// functional, in the H form or the V form (`volume_form`). The job layer checks a job against them
/// before anything runs (jobs/run_job.h), the job reader asks them which fields the functional
/// takes (io/job.cpp), CmcOptions::validate checks the fixed set and the solver against them.
///  - every functional: triangular or tensor nets; triangular n >= 3 with C0 data and >= 6 with
///    C1 data, tensor n, m >= 2 and >= 4; degrees up to kMaxCmcTensorDegree, kMaxCmcTriangularDegree;
///  - dirichlet: any fixed set the net defines; solvers newton, ceres and nlopt in the H form,
///    nlopt only in the V form;
///  - area and mean-curvature: fixed boundary or boundary+adjacent; solvers newton and ceres in
///    both forms;
///  - the fields "start" only with area, "mean_curvature_tolerance" only with mean-curvature.
inline SolverRequirements cmc_requirements(CmcFunctionalKind functional = CmcFunctionalKind::Dirichlet,
                                           bool volume_form = false) {
  SolverRequirements r;
  r.problem = "problem \"cmc\"";
  r.max_degrees = {{NetKind::Tensor, kMaxCmcTensorDegree,
                    "above it the Dirichlet Gram over the free points is numerically singular"},
                   {NetKind::Triangular, kMaxCmcTriangularDegree,
                    "above it the Dirichlet Gram over the free points is numerically singular"}};
  r.nets = {NetKind::Triangular, NetKind::Tensor};
  r.min_degrees = {{NetKind::Triangular, FixedSet::Boundary, 3},
                   {NetKind::Triangular, FixedSet::BoundaryAdjacent, 6},
                   {NetKind::Tensor, FixedSet::Boundary, 2},
                   {NetKind::Tensor, FixedSet::BoundaryAdjacent, 4},
                   {NetKind::Tensor, FixedSet::UBoundaries, 2}};
  if (functional != CmcFunctionalKind::Area) r.refused_fields.push_back({"start", "only with \"functional\": \"area\""});
  if (functional != CmcFunctionalKind::MeanCurvature)
    r.refused_fields.push_back(
        {"mean_curvature_tolerance", "only with \"functional\": \"mean-curvature\""});
  if (functional == CmcFunctionalKind::Dirichlet) {
    r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries};
    r.methods = {"newton", "ceres", "nlopt"};
    if (volume_form) {
      r.methods = {"nlopt"};
      r.method_reason = "a cmc problem with \"V\" needs \"solver\": \"nlopt\"";
    }
    return r;
  }
  r.problem += " with \"functional\": \"" + to_string(functional) + "\"";
  r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent};
  r.methods = {"newton", "ceres"};
  if (functional == CmcFunctionalKind::MeanCurvature)
    r.method_reason = "the mean-curvature functional is solved by the newton or the ceres solver (Levenberg–Marquardt)";
  return r;
}

/// The solver a cmc problem runs when none is given: nlopt for the Dirichlet functional's V form
/// (the only one it takes there, cmc_requirements), newton otherwise.
inline CmcSolver default_cmc_solver(CmcFunctionalKind functional, bool volume_form) {
  return functional == CmcFunctionalKind::Dirichlet && volume_form ? CmcSolver::NLopt : CmcSolver::Newton;
}

/// CmcOptions::mean_curvature_tolerance is in (0, 1) (validate; a job's "mean_curvature_tolerance").
inline bool mean_curvature_tolerance_in_range(double t) { return t > 0.0 && t < 1.0; }

/// The regularity verdict on an area or mean-curvature result (CmcResult::parametrisation): on a
/// 40 x 40 grid away from the corners (margin 0.05) and on rays into each corner margin.
struct ParametrisationCheck {
  bool regular = true;   ///< no verdict below failed
  bool checked = false;  ///< false: not checked (the Dirichlet functional)
  double min_ratio = 0;  ///< min |x_u ∧ x_v| / its mean on the grid
  bool flipped = false;  ///< two neighbouring grid samples with opposite normals
  /// The corner near which the normal flips inside the corner margin, in the domain's (u, v)
  /// (-1, -1: none), the smallest |x_u ∧ x_v| / mean met there, and the boundary's angle at that
  /// corner in degrees on the side of the surface (above 180: reflex).
  double fold_u = -1, fold_v = -1, fold_min_ratio = -1, fold_corner_angle = 0;
};

template <class Net>
struct CmcResult {
  Net net;                     ///< the solution: critical point (D_H, A_H) or least-squares surface (mean-curvature); the last point reached if not converged
  double H = 0.0;              ///< H of `net`: the requested H, the last H reached, or the V-mode multiplier
  double D = 0.0;              ///< Dirichlet energy
  double V = 0.0;              ///< volume 1/3 ∫ <x_u ∧ x_v, x>
  double DH = 0.0;             ///< D + 2HV
  double A = 0.0;              ///< area ∫|x_u ∧ x_v| (computed for every functional)
  double energy = 0.0;         ///< the value of the functional solved: D_H, A_H = A + 2HV, or Φ (mean-curvature)
  CmcFunctionalKind functional = CmcFunctionalKind::Dirichlet;
  int quadrature_points = 0;   ///< area, mean-curvature: Gauss points per direction of the rule minimised
  int quadrature_grading = 0;  ///< area, mean-curvature: its radial grading (1 plain, 3 graded; area_functional.h)
  int quadrature_levels = 0;   ///< area: its geometric radial pieces beyond the first (0: plain or graded; area_functional.h)
  int quadrature_nodes = 0;    ///< area, mean-curvature: its number of nodes (6q² triangular, 8q² tensor)
  int continuation_steps = 0;  ///< accepted continuation steps (H mode; the V form: its steps in V)
  /// converged, iterations (corrector iterations in all; the area functional's also those of
  /// mean-curvature-start, least squares and their D_H start included), residual (mean-curvature: √Φ by the check
  /// rule), message; status Fold past the
  /// fold, NumericalLimit when rounding stops it (singular Gram, eq. (11) missed at the end),
  /// NoConvergence when max_continuation_steps run out or the V-mode solve fails.
  Summary summary;
  /// area: the routes considered, in order, with how each ended and which one was kept.
  AreaRouteLog routes;
  /// area: the regularity of the final net (mean-curvature: filled too).
  ParametrisationCheck parametrisation;
};

/// Solve with the data (prescribed points) of `data`; its free points are ignored.
CmcResult<TriangularNet> solve_cmc(const TriangularNet& data, const CmcOptions& options);
CmcResult<TensorNet> solve_cmc(const TensorNet& data, const CmcOptions& options);

/// The Dirichlet extremal (H = 0, the linear solve): the baseline of the benchmarks.
TriangularNet dirichlet_extremal(const TriangularNet& data, FixedSet fixed);
TensorNet dirichlet_extremal(const TensorNet& data, FixedSet fixed);

}  // namespace bpde
