// dirichlet-start (H form): the paper's D_H critical point at H, corrected on A_H through the
// vanishing Dirichlet regulariser (regulariser_path.cpp), then the final phases where it ends above
// the tolerance.
#include <cmath>
#include <limits>
#include <string>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// The D_H critical point at H, corrected on A_H.
template <class Net>
bool AreaSolve<Net>::from_dirichlet(double H, std::string& note) {
  const CmcResult<Net>& d = dirichlet_solution(H, nullptr);
  if (!d.summary.converged) {
    note = "no D_H critical point at H";
    return false;
  }
  p.base.P = d.net.points();
  choose_rule();
  double h = H;
  const bool ok = homotopy(
      h,
      [&](double hh, double e) {
        p.eps = e;
        const CmcOptions so = stage_options(e);
        choose_rule_for(so.tolerance);
        double th = kFreshDamping;
        CorrectorStats st = o.solver == CmcSolver::Ceres
                                ? ceres_correct(p, hh, so)
                                : area_newton_correct(p, hh, so, 2 * o.max_corrector_iterations, th, o.tolerance);
        summary.iterations += st.iterations;
        return st.ok;
      },
      note);
  p.eps = 0.0;
  if (!ok) return false;
  if (p.residual_at(h, 0.0) > o.tolerance) {
    const CorrectorStats st = finish(h, 2 * o.max_corrector_iterations);
    summary.iterations += st.iterations;
    if (st.ok) note += std::string(note.empty() ? "" : "; ") + "finished by " + final_phases(st, true);
  }
  // No stability test here: the point is tied to the D_H branch point by the homotopy, and a
  // spherical patch larger than a hemisphere is a critical point of A_H but not a minimum.
  return true;
}

#define BPDE_INSTANTIATE(Net) \
  template bool AreaSolve<Net>::from_dirichlet(double, std::string&);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
