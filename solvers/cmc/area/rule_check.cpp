// The final rule check (area_solve.h): the quadrature rule's measured error (against a finer rule,
// also at the cap) at the final net must meet its tolerance; the rule is refined while it does
// not, and the net corrected again with the finer rule. A rule that still misses its tolerance is
// reported (numerical-limit): the first variation is then only known to within that error.
#include <string>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

template <class Net>
void AreaSolve<Net>::rule_check(AreaOutcome& out) {
  if (!out.ok) return;
  choose_rules_again = false;  // refined only, never chosen from the start again
  for (int round = 0; round < kRuleCheckRounds; ++round) {
    const std::shared_ptr<const AreaForm> a0 = p.a;
    const bool rule_ok = refine_rule();
    if (p.a->same_rule(*a0)) {
      if (!rule_ok)
        out = {out.H, false, Status::NumericalLimit,
               "the area quadrature does not reach its error tolerance " + num(kRuleToleranceFactor * o.tolerance) +
                   ": measured error " + num(rule_change) + " with " + std::to_string(a0->points_per_direction()) +
                   " points per direction" +
                   (a0->levels() > 0    ? " on " + std::to_string(a0->levels() + 1) + " geometric pieces"
                    : a0->grading() > 1 ? " (graded)"
                                        : "") +
                   " (a folded or nearly singular parametrisation at a corner); reached after: " + out.message};
      return;
    }
    const CorrectorStats st = o.V ? bordered_correct(*o.V, out.H) : correct(out.H, o.tolerance);
    if (!st.ok) {
      out = {out.H, false, Status::NumericalLimit,
             "the correction with the refined quadrature rule (q = " + std::to_string(p.a->points_per_direction()) +
                 ") stopped at a relative first variation of " + num(st.residual) + soft_verdict(false) +
                 "; reached after: " + out.message};
      return;
    }
  }
}

#define BPDE_INSTANTIATE(Net) template void AreaSolve<Net>::rule_check(AreaOutcome&);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
