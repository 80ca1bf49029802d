// minimal-surface (H = 0, H form): the corrector on A from the Dirichlet extremal, then the final
// phases. A stop above the tolerance but within kAreaStallResidual is a numerical limit (the soft
// tangential modes, as at the end of the other routes); further off there is no critical point
// near the extremal.
#include <cmath>
#include <string>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

template <class Net>
AreaOutcome AreaSolve<Net>::minimal_surface_route() {
  AreaOutcome out;
  out.ok = minimal_surface(o.tolerance);
  out.message = "critical point of the area (H = 0) from the Dirichlet extremal";
  if (out.ok) return out;
  const double r = p.residual_at(0.0, 0.0);
  out.ok = std::isfinite(r) && r <= kAreaStallResidual;
  out.message = out.ok ? "the corrector from the Dirichlet extremal (H = 0) stalled at " + num(r)
                       : "no critical point of the area (H = 0) from the Dirichlet extremal (the corrector "
                         "stopped at a relative first variation of " + num(r) + ")";
  return out;
}

#define BPDE_INSTANTIATE(Net) template AreaOutcome AreaSolve<Net>::minimal_surface_route();
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
