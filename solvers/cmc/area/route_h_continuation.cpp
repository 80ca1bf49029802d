// h-continuation (H form): continuation in H on A_H from the critical point of A at H = 0 (the
// minimal surface, from the Dirichlet extremal), with a positive-definiteness test per step: it
// follows the branch connected to the minimal surface and reports where it turns (status fold).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// Continuation in H on A_H from the critical point of A at H = 0.
template <class Net>
AreaOutcome AreaSolve<Net>::continuation(const Eigen::MatrixX3d& start, const std::vector<int>& fixed_idx, int& steps) {
  const double Ht = o.H;
  p.base.P = start;
  // The start needs only the steps' tolerance: on the tensor catenoid at n = 6 the critical
  // point of A stops at 1.2e-10 (a stationary point in the soft modes), and the continuation
  // was refused as "no critical point of the area (H = 0)".
  if (!minimal_surface(kContinuationStepTolerance))
    return {0.0, false, Status::NoConvergence, "no critical point of the area (H = 0) from the Dirichlet extremal"};
  Eigen::VectorXd tangent;
  if (!strict_minimum(0.0, &tangent))
    return {0.0, false, Status::NoConvergence, "the critical point of the area at H = 0 is not a strict minimum"};
  Eigen::VectorXd y = p.get();
  Net at = make_net(data, p.P());
  // The rule at y: a rejected step puts it back with the net (its final phases may have chosen
  // another at the rejected net).
  std::shared_ptr<const AreaForm> rule_at_y = p.a;
  double change_at_y = rule_change;
  StepController control(Ht, first_step(Ht, p.P(), fixed_idx), o);
  std::string rejected;  // why the last step was rejected, for the fold message
  RouteProgress route_progress(p, kAreaHContinuationStage);  // the way from H = 0 to Ht
  while (!control.reached_target()) {
    if (!control.attempt())
      return {control.h(), false, Status::NoConvergence,
              "A_H continuation stopped at H ≈ " + num(control.h()) +
                  " after max_continuation_steps = " + std::to_string(o.max_continuation_steps) + " attempts"};
    const StepController::Step step = control.propose();
    const bool last = step.hn == Ht;
    const Eigen::VectorXd pred = y + tangent * step.s;
    p.set(pred);
    const Net predicted = make_net(data, p.P());
    // Every step, the last one too, is corrected to 1e-8 (relative first variation; the
    // tolerance if looser), as in the volume continuation, and the end point once more to the
    // tolerance after the loop: on the circle at n = 8 the steps' correctors stalled at
    // 1.0e-11 … 1.04e-11 against 1e-11 from H ≈ −0.9 on, and the step control took that for
    // the fold. A stall of the final correction is a numerical limit, which the solve's end
    // check reports as such.
    const CorrectorStats st = correct(step.hn, kContinuationStepTolerance);
    const Net now = make_net(data, p.P());
    // On the branch when the corrected point lies nearer the prediction than half its distance
    // from the last point, both measured along the surface normals (normal_gap), as in the
    // volume continuation: the corrector also moves the points along the surface, in the nearly
    // singular tangential modes, by as much as the step itself. The point test of the D_H
    // continuation (on_branch) rejected every step on the circle at n = 6 down to a step of
    // 9e-5 from H = 0 (the planar minimal surface, where the tangential modes are exactly
    // singular), though each corrector converged at a strict minimum of A_H.
    const double dev = normal_gap(predicted, now), move = normal_gap(at, now);
    Eigen::VectorXd next;
    const bool near_prediction = st.ok && std::isfinite(move) && dev <= kBranchGapRatio * move + 1e-12 * std::max(1.0, y.norm());
    const bool minimum = near_prediction && strict_minimum(step.hn, last ? nullptr : &next);
    rejected = !st.ok           ? "its corrector stopped at a relative first variation of " + num(st.residual, 3)
               : !near_prediction ? "the corrected surface left the branch"
                            : "the Hessian there is not positive definite beyond the soft modes";
    if (minimum) {
      y = p.get();
      at = now;
      rule_at_y = p.a;
      change_at_y = rule_change;
      if (!last) tangent = next;
      ++steps;
      control.accept(step, st.iterations);
      route_progress.at(std::abs(control.h()) / std::abs(Ht));
    } else {
      p.set(y);
      p.a = rule_at_y;
      rule_change = change_at_y;
      if (!control.reject(step))
        return {control.h(), false, Status::Fold,
                "no critical point of A_H on the branch from H = 0 beyond H ≈ " + num(control.h()) +
                    " (at the last step tried, " + rejected + ")"};
    }
  }
  route_progress.reached();
  correct(Ht, o.tolerance);
  return {Ht, true, Status::Converged,
          "A_H continued from H = 0 to H = " + num(Ht) + " in " + std::to_string(steps) + " step(s)"};
}

#define BPDE_INSTANTIATE(Net) \
  template AreaOutcome AreaSolve<Net>::continuation(const Eigen::MatrixX3d&, const std::vector<int>&, int&);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
