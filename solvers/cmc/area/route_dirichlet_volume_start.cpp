// dirichlet-volume-start (V form): the minimiser of D at V = V0, then the vanishing Dirichlet
// regulariser at fixed V0 (bordered corrector on (Y, H), bordered predictor), then the V form's end.
#include <cmath>
#include <limits>
#include <string>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// The V form of dirichlet-start: the minimiser of D at V = V0 (the nlopt route,
// a critical point of F_1 = D + 2HV at V0 with its multiplier H), then the vanishing Dirichlet
// regulariser at fixed V0: F_ε for ε = 1, 1/10, 1/100, … (ratio adapted as in homotopy()), each
// stage by the bordered corrector from the bordered Euler predictor, until the first variation
// of A_H itself meets the tolerance, then ε = 0. v-continuation (from the critical point of A at
// H = 0) fails on non-conformal data: that start is planar on planar boundaries,
// where A's Hessian is singular in every in-plane direction.
template <class Net>
AreaOutcome AreaSolve<Net>::from_dirichlet_volume(double V0) {
  const CmcResult<Net>& d = dirichlet_solution(o.H, &V0);  // the cached start, not a copy
  if (!d.summary.converged) return {d.H, false, Status::NoConvergence, "no minimiser of D at V = " + num(V0)};
  p.base.P = d.net.points();
  double H = d.H;
  choose_rule();
  const std::string from = "from the minimiser of D at V = " + num(V0) + " (H = " + num(d.H) + ")";
  std::string note;
  const bool ok = homotopy(
      H,
      [&](double& h, double e) {
        p.eps = e;
        const CmcOptions so = stage_options(e);
        choose_rule_for(so.tolerance);
        theta = kFreshDamping;
        return bordered_correct(V0, h, e == 0.0 ? o.tolerance : so.tolerance).ok;
      },
      note, &V0);
  if (!ok) {
    p.eps = 0.0;
    return {H, false, Status::NoConvergence, note + " at fixed V " + from};
  }
  if (!note.empty()) note = " (" + note + ")";
  p.eps = 0.0;
  note += finish_volume(V0, H);
  return {H, true, Status::Converged, "the volume-constrained critical point of A " + from + note};
}

#define BPDE_INSTANTIATE(Net) \
  template AreaOutcome AreaSolve<Net>::from_dirichlet_volume(double);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
