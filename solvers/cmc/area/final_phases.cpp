// The final phases on A_H at ε = 0 (area_solve.h): the truncated Newton phase and the soft-mode
// phase after it (solver newton) or the soft-mode phase by Ceres (solver ceres), the corrector that
// ends in them, and the V form's end at its multiplier H.
#include <algorithm>
#include <cmath>
#include <string>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// The rule is chosen again where it missed its tolerance at the net where it was chosen: a start
// that nearly folds at a corner (on a wavy boundary curve the Dirichlet extremal takes the graded
// q = 64 rule, 32 768 nodes on a tensor net, and still misses by 1.7e-4) would otherwise keep that
// rule through the final phases, the longest part of a hard solve, where the surface reached needs
// far fewer nodes (there the plain q = 26 rule, 5408; docs/performance_measurements.md). Here, and
// during the truncated Newton phase, where the net moves on from here.
template <class Net>
CorrectorStats AreaSolve<Net>::finish(double H, int max_iterations) {
  CorrectorStats t;
  if (p.sparse && 3 * p.k() > kDenseFinalPhasesLimit) {  // a large complex: no dense phases
    t.residual = p.residual(H);
    t.ok = t.residual <= o.tolerance;
    return t;
  }
  p.refresh_rule = [this] {
    if (!choose_rules_again || rule_change <= kRuleToleranceFactor * o.tolerance) return false;
    const std::shared_ptr<const AreaForm> a0 = p.a;
    choose_rule();
    const bool changed = p.a != a0;
    if (changed && record) record->add_phase(AreaPhase::RuleRefresh, 1);
    return changed;
  };
  p.refresh_rule();
  if (o.solver == CmcSolver::Ceres) {
    t = area_soft_mode_phase(p, H, o, kSoftModeIterationsPerCorrector * o.max_corrector_iterations);
    t.soft_iterations = t.iterations;
  } else {
    t = area_truncated_newton(p, H, o, max_iterations);
  }
  p.refresh_rule = nullptr;
  stationary_end = t.soft_stationary ? SoftEndMark{SoftModeEnd::Stationary, p.P(), p.a} : SoftEndMark{};
  degenerate_end = t.trust_region_blocked ? SoftEndMark{SoftModeEnd::DegenerateBound, p.P(), p.a} : SoftEndMark{};
  if (record) {
    record->add_phase(AreaPhase::TruncatedNewton, t.iterations - t.soft_iterations);
    record->add_phase(o.solver == CmcSolver::Ceres ? AreaPhase::SoftModeCeres : AreaPhase::SoftModeLm,
                      t.soft_iterations);
    record->add_phase(AreaPhase::TrustRegion, t.trust_region_iterations);
  }
  return t;
}

template <class Net>
std::string AreaSolve<Net>::final_phases(const CorrectorStats& t, bool counts) {
  const int truncated = t.iterations - t.soft_iterations;
  auto phase = [&](const char* name, int it) {
    return std::string(name) + (counts ? " in " + std::to_string(it) + " iteration(s)" : "");
  };
  std::string s = truncated > 0 ? phase("the truncated Newton phase", truncated) : "";
  if (t.soft_iterations > 0) s += (s.empty() ? "" : " and ") + phase("the soft-mode phase", t.soft_iterations);
  if (t.trust_region_iterations > 0)
    s += counts ? " (" + std::to_string(t.trust_region_iterations) + " of them trust-region steps on A_H)"
                : " (with trust-region steps on A_H)";
  return s;
}

// The final phases aim at the tolerance itself, whatever `tol`: on the circle past H = −0.8
// (n = 6 and 8) continuation steps whose final phases stopped at 1e-8 left points from which the
// next steps' Hessians were not positive definite, and the continuation ended at H ≈ −0.85 and
// −0.96 instead of the hemisphere.
template <class Net>
CorrectorStats AreaSolve<Net>::correct(double H, double tol) {
  CmcOptions co = o;
  co.tolerance = std::max(tol, o.tolerance);
  CorrectorStats st = o.solver == CmcSolver::Ceres
                          ? ceres_correct(p, H, co)
                          : area_newton_correct(p, H, co, 2 * o.max_corrector_iterations, theta, 0.0);
  if (!st.ok && p.eps == 0.0 && std::isfinite(st.residual)) {
    // The corrector stalls in the tangential valley: finish with the final phases.
    const CorrectorStats t = finish(H, o.max_corrector_iterations);
    st.iterations += t.iterations;
    st.ok = t.ok || t.residual <= co.tolerance;
    st.residual = t.residual;
  }
  summary.iterations += st.iterations;
  return st;
}

// The V form's critical point is the A_H critical point at its multiplier H: the H form's final
// phases at the H reached, then bordered iterations back onto V = V0.
template <class Net>
std::string AreaSolve<Net>::finish_volume(double V0, double& H) {
  if (vresidual(V0, H) <= o.tolerance) return "";
  const Eigen::VectorXd y = p.get();
  const std::shared_ptr<const AreaForm> a0 = p.a;
  const double Hs = H, change0 = rule_change;
  double r0 = vresidual(V0, H);
  const CorrectorStats t = finish(H, 2 * o.max_corrector_iterations);
  summary.iterations += t.iterations;
  theta = kVolumeReturnDamping;
  bordered_correct(V0, H, o.tolerance, kVolumeReturnIterations);
  if (p.a != a0) {
    // finish chose another rule: the start's residual on it, so that the two compare.
    const Eigen::VectorXd y1 = p.get();
    p.set(y);
    r0 = vresidual(V0, Hs);
    p.set(y1);
  }
  if (!(vresidual(V0, H) < r0)) {
    p.set(y);
    p.a = a0;
    rule_change = change0;
    H = Hs;
    return "";
  }
  const std::string phases = final_phases(t, false);
  return "; finished by " +
         (phases.empty() ? std::string("the bordered corrector") : phases + " at H and the bordered corrector");
}

template <class Net>
bool AreaSolve<Net>::minimal_surface(double tol) {
  choose_rule();
  return correct(0.0, tol).ok;
}

#define BPDE_INSTANTIATE(Net)                                                        \
  template CorrectorStats AreaSolve<Net>::finish(double, int);                      \
  template std::string AreaSolve<Net>::final_phases(const CorrectorStats&, bool);   \
  template CorrectorStats AreaSolve<Net>::correct(double, double);                  \
  template std::string AreaSolve<Net>::finish_volume(double, double&);              \
  template bool AreaSolve<Net>::minimal_surface(double);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
