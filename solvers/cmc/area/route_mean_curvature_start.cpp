// mean-curvature-start (both forms): the least-squares mean-curvature surface, then a few Newton
// iterations on A_H (the bordered corrector at V0 in the V form) and, where they stall, the final
// phases.
#include <cmath>
#include <limits>
#include <string>
#include <algorithm>
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// Both forms (docs/cmc_algorithm.md, "mean-curvature-start"): the least-squares
// mean-curvature surface (the functional "mean-curvature" by the same solver, from the D start
// of dirichlet_solution; at H within kMeanCurvatureStartIterations, or in the V form at V0 with
// its H), converged or not (where √Φ stops above its tolerance the surface is still far nearer a
// critical point of A_H than the D_H critical point is), then at most kMeanCurvatureStartCorrector Newton iterations on A_H itself
// (the bordered corrector at V0 in the V form), no regulariser, and where they stall the final
// phases (finish; finish_volume in the V form). Kept when they meet the tolerance at a regular
// net whose rule meets its own; otherwise the net, rule, damping, ε, H and the soft-mode verdict
// go back to what they were, `note` says how it ended, and the driver goes on with the Dirichlet
// routes. Measured on the circle (H = −0.5, −0.9, n = 8 … 16 where the least
// squares converge): 2–5 iterations, and the critical point reached lies 4–80× nearer the sphere
// than the one the routes from the D_H critical point reach (both with first variations below
// 1e-11: A_H is nearly flat along its tangential valley, and Φ pins the geometry). From least
// squares above their tolerance: the circle at n = 6 and at H = −0.9, n = 8, the
// helicoid at n = 4 and the tensor catenoid at n = 6 and 8 converge this way, the last three
// where the routes from the D_H point stop at a numerical limit or take twice as long; the
// tensor catenoid at n = 12 from √Φ 2.3e-6 after the H form's 300 iterations.
template <class Net>
bool AreaSolve<Net>::from_mean_curvature(const double* V0, double& H, std::string& note, int& steps) {
  CmcOptions om = o;
  om.functional = CmcFunctionalKind::MeanCurvature;
  if (!V0) om.max_least_squares_iterations = std::min(o.max_least_squares_iterations, kMeanCurvatureStartIterations);
  const CmcResult<Net> m = solve_mean_curvature(data, om, &dirichlet_solution(o.H, V0));
  summary.iterations += m.summary.iterations;
  if (record) {
    record->least_squares_residual = m.summary.residual;
    record->least_squares_converged = m.summary.converged;
  }
  const std::string start = "the least-squares mean-curvature surface (√Φ = " + num(m.summary.residual, 3) +
                            (m.summary.converged                                      ? std::string()
                             : m.summary.residual > o.mean_curvature_tolerance ? ", above its tolerance"
                                                                                 : ", not converged") +
                            ")";
  if (!m.net.points().allFinite() || !std::isfinite(m.H)) {
    note = start + " is not finite";
    return false;
  }
  const State before = save();
  const double H0 = H;
  p.base.P = m.net.points();
  p.eps = 0.0;
  if (V0) H = m.H;
  bool rule_ok = choose_rule();
  theta = kFreshDamping;
  // At most kMeanCurvatureStartCorrector Newton iterations on A_H (V form: bordered, at V0).
  auto newton = [&] {
    if (V0) return bordered_correct(*V0, H, o.tolerance, kMeanCurvatureStartCorrector);
    CorrectorStats c;
    if (o.solver == CmcSolver::Ceres) {
      CmcOptions co = o;
      co.max_corrector_iterations = kMeanCurvatureStartCorrector;
      c = ceres_correct(p, H, co);
    } else {
      c = area_newton_correct(p, H, o, kMeanCurvatureStartCorrector, theta, 0.0);
    }
    summary.iterations += c.iterations;
    return c;
  };
  CorrectorStats st = newton();
  std::string finished;
  if (!st.ok && std::isfinite(st.residual)) {
    if (V0) {
      finished = finish_volume(*V0, H);
      st.residual = vresidual(*V0, H);
      st.ok = st.residual <= o.tolerance;
    } else {
      const CorrectorStats t = finish(H, o.max_corrector_iterations);
      summary.iterations += t.iterations;
      st.ok = t.ok;
      st.residual = t.residual;
      const std::string phases = final_phases(t, true);
      if (!phases.empty()) finished = " and " + phases;
    }
    // The rule in use now (the final phases choose it again where it missed its tolerance).
    rule_ok = rule_change <= 0.1 * o.tolerance;
    // The final phases can move the net far along the surface (the tensor catenoid at n = 6:
    // control points by up to 1.4): at a regular net reached the rule is checked again, refined
    // where it misses its tolerance there, and the Newton iterations run again with the finer
    // one. (Not at a degenerate net, which this route gives up anyway: there the rule would be
    // refined to its cap in vain, 0.9 s on the sphere patch at n = 8.)
    const auto is_regular = [&] {
      const Net reached = make_net(data, p.P());
      return regularity(reached, area(reached)).ok;
    };
    if (st.ok && rule_ok && is_regular()) {
      const std::shared_ptr<const AreaForm> a0 = p.a;
      rule_ok = refine_rule();
      if (rule_ok && !p.a->same_rule(*a0)) {
        const CorrectorStats again = newton();
        st.ok = again.ok;
        st.residual = again.residual;
        st.iterations += again.iterations;
        finished += " and again with a finer rule in " + std::to_string(again.iterations);
      }
    }
  }
  // Kept only where the routes below would not do better by the common end's tests: the rule
  // meets its tolerance at the net and the parametrisation is regular.
  const Net net = make_net(data, p.P());
  const bool regular = st.ok && regularity(net, area(net)).ok;
  if (st.ok && rule_ok && regular) {
    note = start + " corrected on A_H in " + std::to_string(st.iterations) + " iteration(s)" + finished;
    if (V0) steps = m.continuation_steps;
    return true;
  }
  if (!V0 && !st.ok && rule_ok && st.residual <= kAreaStallResidual && regularity(net, area(net)).ok)
    stalled_mean_curvature_end = RouteEnd{save(), start + " corrected on A_H in " + std::to_string(st.iterations) +
                                      " iteration(s)" + finished + ", to " + num(st.residual, 3)};
  note = start + (!st.ok ? " was corrected on A_H to " + num(st.residual, 3) + " only"
                  : !rule_ok ? " was corrected on A_H, but the area rule misses its tolerance there"
                             : " was corrected on A_H to a degenerate parametrisation");
  restore(before);
  H = H0;
  return false;
}

#define BPDE_INSTANTIATE(Net) \
  template bool AreaSolve<Net>::from_mean_curvature(const double*, double&, std::string&, int&);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
