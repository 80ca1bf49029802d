// smaller-volume-start (V form): dirichlet-volume-start at a smaller volume V1 between the
// Dirichlet extremal's and V0, then continued in V to V0 (continue_volume, route_v_continuation.cpp).
#include <cmath>
#include <limits>
#include <string>
#include <algorithm>
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// dirichlet-volume-start at V1 = Vref + (V0 − Vref)/k for k in kSmallerVolumeDivisors (Vref the volume of the Dirichlet extremal, so V1 lies between the nearly
// minimal surface and V0 wherever the origin is: V changes by a constant with the origin, the
// same for every surface with this boundary), the first whose start meets 1e-8 (relative; the
// tolerance if looser) and from which the continuation reaches V0, each step corrected to the
// same (the crawl below it is left to the end), then the bordered corrector at V0 and the V
// form's end (finish_volume).
// Measured on the circle past the hemisphere (docs/cmc_measurements.md): the larger caps, whose D
// minimiser keeps the regulariser above ε = 0.018 (H = −0.7). k = 4 costs 7 s more at n = 10,
// H = −0.7, where dirichlet-volume-start fails at V1 = 2.88, and at n = 12 it ends there at
// 9.2e-7, too far for a start.
template <class Net>
AreaOutcome AreaSolve<Net>::volume_continuation_from_smaller(double V0, double Vref, int& steps) {
  std::string tried;
  for (const double k : kSmallerVolumeDivisors) {
    const double V1 = Vref + (V0 - Vref) / k;
    if (!(V1 != V0)) break;
    const double step_tol = std::max(o.tolerance, kContinuationStepTolerance);
    const AreaOutcome start = from_dirichlet_volume(V1);
    // dirichlet-volume-start may end "ok" above the tolerance (a numerical limit); a start for the
    // continuation must meet the steps' tolerance.
    const double r1 = start.ok ? vresidual(V1, start.H) : std::numeric_limits<double>::infinity();
    if (!(r1 <= step_tol)) {
      tried += (tried.empty() ? "" : "; ") + num(V1) + ": " +
               (start.ok ? "dirichlet-volume-start ended at " + num(r1) : start.message);
      continue;
    }
    steps = 0;
    const AreaOutcome out = continue_volume(V1, start.H, V0, steps, step_tol, true);
    if (!out.ok) {
      tried += (tried.empty() ? "" : "; ") + num(V1) + ": " + out.message;
      continue;
    }
    if (record) record->start_volume = V1;
    double H = out.H;
    choose_rule();
    theta = kFreshDamping;
    bordered_correct(V0, H);
    const std::string note = finish_volume(V0, H);
    return {H, true, Status::Converged,
            "the volume-constrained critical point of A continued in V from V1 = " + num(V1) + " (H = " +
                num(start.H) + ", from the minimiser of D there) in " + std::to_string(steps) + " step(s)" + note};
  }
  steps = 0;
  return {0.0, false, Status::NoConvergence,
          "no continuation in V from smaller volumes (V1 = " + (tried.empty() ? std::string("none") : tried) + ")"};
}

#define BPDE_INSTANTIATE(Net) \
  template AreaOutcome AreaSolve<Net>::volume_continuation_from_smaller(double, double, int&);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
