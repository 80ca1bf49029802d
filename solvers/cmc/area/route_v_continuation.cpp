// v-continuation (V form): continuation in V along the volume-constrained critical points of A,
// from the minimal surface (V = V_min) to V0; continue_volume is shared with smaller-volume-start.
#include <cmath>
#include <limits>
#include <string>
#include <algorithm>

#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// The last V-form route (alone with "start": "minimal-surface"): continuation in V from the
// critical point of A at H = 0 (V = V_min) to V0, as smaller-volume-start continues from V1: the
// start and every step to max(tolerance, kContinuationStepTolerance) with fresh damping, then the
// bordered corrector and the final phases at V0. Measured on the circle (H = −0.5 cap's V0):
// n = 6, 8, 10 converge in 10, 2 and 13 steps. With every step to the tolerance itself and the
// damping carried over from the start, the first step stalls at 5e-10 above 1e-11 and the steps
// below it find no point ("beyond V ≈ 1e-4" at n = 6 and 8).
template <class Net>
AreaOutcome AreaSolve<Net>::volume_continuation(const Eigen::MatrixX3d& start, int& steps) {
  p.base.P = start;
  const double step_tol = std::max(o.tolerance, kContinuationStepTolerance);
  if (!minimal_surface(step_tol))
    return {0.0, false, Status::NoConvergence, "no critical point of the area (H = 0) from the Dirichlet extremal"};
  const double Vmin = p.base.f->volume_form().value(p.P());
  AreaOutcome out = continue_volume(Vmin, 0.0, *o.V, steps, step_tol, true);
  if (!out.ok) return out;
  double H = out.H;
  choose_rule();
  theta = kFreshDamping;
  bordered_correct(*o.V, H);
  const std::string note = finish_volume(*o.V, H);
  return {H, true, Status::Converged,
          "V continued from the minimal surface (V = " + num(Vmin) + ") in " + std::to_string(steps) + " step(s)" +
              note};
}

// Continuation in V along the volume-constrained critical points of A, from the one in p (volume
// Vs, multiplier H) to V0: the Euler predictor along the tangent per unit V (K dY + 2∇V dH = 0,
// ∇V·dY = 1; K regularised by 1e-8 C), the bordered corrector to `step_tol` at each step, and the
// step control of the H continuation (StepController over V − Vs). A corrected point is on the
// branch when it lies closer to the prediction than half its distance to the last point, both
// measured along the surface normals (normal_gap): the corrector moves the points along the
// surface too, in the nearly singular tangential modes, by as much as the step itself (measured
// on the circle past the hemisphere: the point test of the H continuation, on_branch, then
// rejected every step from V = 1.81 on).
template <class Net>
AreaOutcome AreaSolve<Net>::continue_volume(double Vs, double H, double V0, int& steps, double step_tol, bool fresh_damping) {
  auto tangent = [&](double h, Eigen::VectorXd& dY, double& dH) {
    const SymFactor fac(p.hessian(h) + kVolumeTangentShift * p.dense_C());
    const Eigen::VectorXd gV = p.volume_gradient(), b = fac.solve(gV);
    const double s = gV.dot(b);
    if (!(std::abs(s) > 0) || !b.allFinite()) return false;
    dY = b / s;
    dH = -1.0 / (2.0 * s);
    return true;
  };
  Eigen::VectorXd dY;
  double dH = 0;
  if (!tangent(H, dY, dH))
    return {H, false, Status::NoConvergence, "the volume has no gradient at the start of the volume continuation"};
  Eigen::VectorXd y = p.get();
  Net last = make_net(data, p.P());
  const double target = V0 - Vs;
  StepController control(target, target, o);
  std::string rejected;  // why the last step was rejected, for the message
  RouteProgress route_progress(p, kAreaVContinuationStage);  // the way from Vs to V0
  while (!control.reached_target()) {
    if (!control.attempt())
      return {H, false, Status::NoConvergence,
              "volume continuation stopped at V ≈ " + num(Vs + control.h()) + " after max_continuation_steps"};
    const StepController::Step step = control.propose();
    p.set(y + dY * step.s);
    const Net pred = make_net(data, p.P());
    double Hn = H + dH * step.s;
    if (fresh_damping) theta = kFreshDamping;
    const CorrectorStats st = bordered_correct(Vs + step.hn, Hn, step_tol);
    const Net now = make_net(data, p.P());
    const double dev = normal_gap(pred, now), move = normal_gap(last, now);
    const bool near_prediction = st.ok && std::isfinite(move) && dev <= kBranchGapRatio * move + 1e-12 * std::max(1.0, y.norm());
    rejected = !st.ok ? "its corrector stopped at a relative residual of " + num(st.residual, 3)
               : !near_prediction ? "the corrected surface left the branch"
                                  : "the volume has no gradient there";
    if (near_prediction && tangent(Hn, dY, dH)) {
      y = p.get();
      last = now;
      H = Hn;
      ++steps;
      control.accept(step, st.iterations);
      route_progress.at(control.h() / target);
    } else {
      p.set(y);  // dY, dH are still the tangent at y (tangent() writes only when it succeeds)
      if (!control.reject(step))
        return {H, false, Status::NoConvergence,
                "no volume-constrained critical point of the area beyond V ≈ " + num(Vs + control.h()) +
                    " (at the last step tried, " + rejected + ")"};
    }
  }
  route_progress.reached();
  return {H, true, Status::Converged,
          "V continued from V = " + num(Vs) + " in " + std::to_string(steps) + " step(s)"};
}

#define BPDE_INSTANTIATE(Net) \
  template AreaOutcome AreaSolve<Net>::volume_continuation(const Eigen::MatrixX3d&, int&); \
  template AreaOutcome AreaSolve<Net>::continue_volume(double, double, double, int&, double, bool);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
