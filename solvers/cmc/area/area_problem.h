#pragma once
// Internal to solvers/cmc/*.cpp: the A_H = A + 2HV problem over the free control points (cmc.h,
// "The area functional"), in the vector layout of cmc_problem.h (y(3a + c) = P(free[a], c)).
#include <functional>

#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/solvers/cmc/area/sparse_terms.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {

/// The progress stages of the area solve: the solve (the decades of the Dirichlet regulariser
/// removed) and its continuation routes (the way along H, or along V, to the target).
inline constexpr std::string_view kAreaStage = "cmc area";
inline constexpr std::string_view kAreaHContinuationStage = "cmc area h-continuation";
inline constexpr std::string_view kAreaVContinuationStage = "cmc area v-continuation";

struct AreaProblem {
  CmcProblem base;                    ///< the Dirichlet Gram and V, the free points and P
  std::shared_ptr<const AreaForm> a;  ///< the quadrature rule in use
  /// The Dirichlet Gram over the free points ⊗ Id_3 (dense; empty where `sparse` is set: then
  /// dense_C() builds it from sparse->C the first time a dense phase asks for it).
  mutable Eigen::MatrixXd C;
  /// A surface of several patches: the sparse Gram and Hessians (sparse_terms.h); the corrector
  /// and the predictors then factor sparse matrices. Null for one patch.
  std::shared_ptr<const SparseAreaTerms> sparse;
  const Eigen::MatrixXd& dense_C() const {
    if (C.size() == 0 && sparse) C = Eigen::MatrixXd(sparse->C);
    return C;
  }
  /// The weight of the Dirichlet regulariser: the functional is F_ε = A_H + ε(D - A)
  /// = (1-ε)A + εD + 2HV (ε = 1: the paper's D_H; ε = 0: A_H).
  double eps = 0.0;
  /// Progress (core/progress.h): every residual_at reports `progress_stage` ("cmc area", or a
  /// continuation route's stage while it runs: RouteProgress) again at `progress_done`, the
  /// fraction last reported, so that a progress line keeps showing the time through the final
  /// phases (two minutes and more on hard cases, of no known length); null: none.
  const ProgressFn* progress = nullptr;
  std::string_view progress_stage = kAreaStage;
  double progress_done = 0.0;
  /// The rule chosen again at the current net where the rule in use missed its tolerance at the
  /// net where it was chosen (AreaSolve::finish, final_phases.cpp); true when `a` changed. Called by
  /// area_truncated_newton every kRuleRefreshEvery iterations and before the soft-mode phase. Null: never.
  std::function<bool()> refresh_rule;

  int k() const { return base.k(); }
  Eigen::VectorXd get() const { return base.get(); }
  void set(const Eigen::VectorXd& y) { base.set(y); }
  const Eigen::MatrixX3d& P() const { return base.P; }
  double area() const { return a->value(base.P); }
  /// F_ε (A_H when eps = 0).
  double value(double H) const;
  /// Free rows of ∇F_ε (3k).
  Eigen::VectorXd gradient(double H) const;
  /// 3k x 3k Hessian of F_ε over the free points.
  Eigen::MatrixXd hessian(double H) const;
  /// The same, sparse (needs `sparse`).
  Eigen::SparseMatrix<double> hessian_sparse(double H) const;
  /// The Dirichlet Gram over the free points ⊗ Id_3, sparse (needs `sparse`).
  const Eigen::SparseMatrix<double>& sparse_C() const { return sparse->C; }
  /// Free rows of ∇V (3k).
  Eigen::VectorXd volume_gradient() const { return base.volume_gradient(); }
  /// max |∇F_ε| / max ((1-ε)S_A + ε Σ_J|C_IJ||P_J| + 2|H| S_V) over the free rows (AreaForm /
  /// VolumeForm scales); the gradient into g when given; +inf when not finite.
  double residual(double H, Eigen::VectorXd* g = nullptr) const { return residual_at(H, eps, g); }
  /// The same with another ε (ε = 0: the first variation of A_H).
  double residual_at(double H, double e, Eigen::VectorXd* g = nullptr) const;
};

/// A continuation route's progress stage while it lives: reports `stage` at 0, then the fraction
/// of the way to the target at each accepted step (at()), and 1 once the target is reached
/// (reached()); the problem's residual evaluations report the route's stage in between. The
/// stage and fraction before are restored at the end.
class RouteProgress {
 public:
  RouteProgress(AreaProblem& p, std::string_view stage) : p_(p), stage_(p.progress_stage), done_(p.progress_done) {
    p_.progress_stage = stage;
    p_.progress_done = 0.0;
    tell();
  }
  ~RouteProgress() {
    p_.progress_stage = stage_;
    p_.progress_done = done_;
  }
  RouteProgress(const RouteProgress&) = delete;
  RouteProgress& operator=(const RouteProgress&) = delete;
  /// `fraction` of the way done (kept below 1 until reached(), never falling).
  void at(double fraction) {
    if (!(fraction >= 0)) return;
    p_.progress_done = std::max(p_.progress_done, std::min(fraction, 0.999));
    tell();
  }
  /// The target is reached: the stage ends (reported once) and the stage before is back.
  void reached() {
    p_.progress_done = 1.0;
    tell();
    p_.progress_stage = stage_;
    p_.progress_done = done_;
  }

 private:
  void tell() const {
    if (p_.progress) report(*p_.progress, p_.progress_stage, p_.progress_done, 1.0);
  }
  AreaProblem& p_;
  std::string_view stage_;
  double done_;
};

/// The regularised Newton corrector of F_ε at fixed H from problem.P (cmc.h). theta carries the
/// regularisation factor from one call to the next. With target > 0 and ε > 0 it also stops when
/// the first variation of A_H itself is below target.
CorrectorStats area_newton_correct(AreaProblem& p, double H, const CmcOptions& o, int max_iterations, double& theta,
                                   double target);
/// The final Newton phase on A_H (ε = 0) with the Hessian solve truncated to the modes above a relative
/// eigenvalue cut (correctors.cpp); ok when the first variation reaches o.tolerance.
CorrectorStats area_truncated_newton(AreaProblem& p, double H, const CmcOptions& o, int max_iterations);
/// The soft-mode phase on A_H (ε = 0), run by area_truncated_newton when it stops above the
/// tolerance: the hard modes eliminated by chord Newton steps, Levenberg–Marquardt on the reduced
/// first variation over the soft modes (soft_mode_phase.cpp, where the method is explained).
/// Leaves p at the point of smallest residual met; ok when it reaches o.tolerance;
/// soft_stationary when no step lowers the reduced first variation.
CorrectorStats area_soft_mode_phase(AreaProblem& p, double H, const CmcOptions& o, int max_iterations);
/// Regularity of a solved net on a 40 × 40 grid away from the corners (margin 0.05): |x_u ∧ x_v|
/// relative to its mean A / |domain| at least 1e-3, and no two neighbouring samples with opposite
/// normals (regularity.cpp). Shared by the area and the mean-curvature solves.
struct Regularity {
  bool ok = true;
  double min_ratio = 0;  ///< min |N| / mean |N| on the grid
  bool flipped = false;  ///< two neighbouring samples with opposite normals
  /// The corner near which the normal flips (a fold inside the corner margin, which the grid
  /// leaves out), in the domain's (u, v), and the smallest |N| / mean |N| met there; none: -1.
  double fold_u = -1, fold_v = -1, fold_min_ratio = -1;
  /// The boundary's angle at that corner in degrees, on the side of the surface (above 180:
  /// reflex, the edges' tangents give a corner normal against the surface's).
  double fold_corner_angle = 0;
  /// The words of a verdict that is not ok: "|x_u ∧ x_v| falls to … of its mean inside the patch
  /// [and the normal flips]" or "the normal flips near the corner (u, v) = (…) …".
  std::string describe() const;
};
/// The public form of a verdict (CmcResult::parametrisation).
inline ParametrisationCheck parametrisation_check(const Regularity& r) {
  return {r.ok, true, r.min_ratio, r.flipped, r.fold_u, r.fold_v, r.fold_min_ratio, r.fold_corner_angle};
}
Regularity regularity(const TriangularNet& net, double A);
Regularity regularity(const TensorNet& net, double A);
/// A complex (complex_net.h): the patches' verdicts, each patch on its own grid with its own area
/// (A unused); ok when every patch is.
Regularity regularity(const ComplexNet& net, double A);
/// The verdict on a result: regularity() and, where that is ok, folds inside the corner margins
/// (rays from each corner down to 3e-6 of the edge; the normal must not turn over). Not used
/// between the routes of a solve: a fold at a corner whose boundary angle is reflex is in every
/// net with those edges, so it cannot choose between them.
Regularity final_regularity(const TriangularNet& net, double A);
Regularity final_regularity(const TensorNet& net, double A);
Regularity final_regularity(const ComplexNet& net, double A);
/// max over the samples (a/10, b/10) of the domain, without the corners (the regularity test's
/// margin 0.05), of |<x_b − x_a, N_a>|, N_a the unit normal of a: how far surface b lies from
/// surface a along a's normals (the branch test of the area's H and V continuations, regularity.cpp). A motion of
/// the points along the surface (a reparametrisation, the nearly singular directions of A_H)
/// changes it only to second order, where the distance of the points themselves changes to first
/// order. +inf where a's normal vanishes at a sample. a and b of the same degree.
double normal_gap(const TriangularNet& a, const TriangularNet& b);
double normal_gap(const TensorNet& a, const TensorNet& b);
/// A complex: the largest of the patches'.
double normal_gap(const ComplexNet& a, const ComplexNet& b);

/// The least-squares mean-curvature functional (cmc.h; cmc_mean_curvature.cpp). options are validated.
CmcResult<TriangularNet> solve_mean_curvature(const TriangularNet& data, const CmcOptions& options);
CmcResult<TensorNet> solve_mean_curvature(const TensorNet& data, const CmcOptions& options);
/// A complex: at most kMaxMeanCurvatureCoordinates free coordinates and solver newton
/// (UnsupportedProblem otherwise; complex_net.h).
CmcResult<ComplexNet> solve_mean_curvature(const ComplexNet& data, const CmcOptions& options);
/// The same from the D start already solved (`dirichlet`: solve_cmc of data with options' H and V,
/// functional dirichlet, solver newton in the H form and nlopt in the V form), taken instead of
/// solving it again (the area functional solves it before mean-curvature-start); null: solved here.
CmcResult<TriangularNet> solve_mean_curvature(const TriangularNet& data, const CmcOptions& options,
                                              const CmcResult<TriangularNet>* dirichlet);
CmcResult<TensorNet> solve_mean_curvature(const TensorNet& data, const CmcOptions& options,
                                          const CmcResult<TensorNet>* dirichlet);
CmcResult<ComplexNet> solve_mean_curvature(const ComplexNet& data, const CmcOptions& options,
                                           const CmcResult<ComplexNet>* dirichlet);

/// Ceres LM on the residual blocks ∇A_H (cmc_ceres.cpp).
CorrectorStats ceres_correct(AreaProblem& p, double H, const CmcOptions& o);

/// The V form's corrector by Ceres (cmc_ceres.cpp): LM on the 3k + 1 residuals (∇F_ε + 2H∇V over
/// the free points; (V − V0)/|∇V|) over (Y, H), with the exact bordered Jacobian
/// [∇²F_ε + 2H∇²V, 2∇V; ∇Vᵀ/|∇V|, 0], until `residual(H)` (the V form's stopping measure, at the
/// current p.eps) is at most tol, or max_iterations steps. H in and out.
CorrectorStats ceres_bordered_correct(AreaProblem& p, double V0, double& H, double tol, int max_iterations,
                                      const std::function<double(double)>& residual);

}  // namespace bpde::cmc_detail
