// The V form's corrector (area_solve.h): bordered regularised Newton on (Y, H) for
// ∇F_ε + 2H∇V = 0, V = V0 at fixed V0 (F_ε at the current p.eps; ε = 0: A itself). Each iteration
// solves (K + θ r C) [a b] = [g ∇V] and takes the step −a − 2 dH b, dH from the volume row; a step
// is accepted when it lowers the V form's residual (kBorderedDamping). Solver ceres: the same
// residuals and stopping measure by Ceres' Levenberg–Marquardt (cmc_ceres.cpp).
#include <cmath>
#include <functional>
#include <limits>

#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

template <class Net>
CorrectorStats AreaSolve<Net>::bordered_correct(double V0, double& H, double tol, int max_iterations) {
  if (tol < 0) tol = o.tolerance;
  if (max_iterations < 0) max_iterations = 2 * o.max_corrector_iterations;
  const optim::Damping& damping = kBorderedDamping;
  CorrectorStats st;
  const VolumeForm& vf = p.base.f->volume_form();
  auto resid = [&](double h, Eigen::VectorXd& g, double& c) {
    const double rg = p.residual(h, &g);
    c = vf.value(p.P()) - V0;
    const double vs = vf.value_scale(p.P());
    return std::max(rg, vs > 0 ? std::abs(c) / vs : std::abs(c));
  };
  if (o.solver == CmcSolver::Ceres) {
    const std::function<double(double)> measure = [&](double h) {
      Eigen::VectorXd g;
      double c = 0;
      return resid(h, g, c);
    };
    st = ceres_bordered_correct(p, V0, H, tol, max_iterations, measure);
    summary.iterations += st.iterations;
    return st;
  }
  Eigen::VectorXd g;
  double c = 0;
  st.residual = resid(H, g, c);
  for (int it = 0;; ++it) {
    if (!std::isfinite(st.residual)) return st;
    if (st.residual <= tol) {
      st.ok = true;
      return st;
    }
    if (it >= max_iterations) return st;
    const Eigen::MatrixXd K = p.hessian(H);
    const Eigen::VectorXd gV = p.volume_gradient(), y = p.get();
    bool accepted = false;
    for (int tries = 0; tries < damping.max_tries && !accepted; ++tries) {
      const SymFactor fac(K + theta * st.residual * p.dense_C());
      const Eigen::VectorXd a = fac.solve(g), b = fac.solve(gV);
      const double den = 2.0 * gV.dot(b);
      if (!(std::abs(den) > 0) || !a.allFinite() || !b.allFinite()) {
        damping.rejected(theta);
        continue;
      }
      const double dH = (c - gV.dot(a)) / den;
      p.set(y - a - 2.0 * dH * b);
      Eigen::VectorXd gn;
      double cn = 0;
      const double rn = p.a->min_normal(p.P()) > 0 ? resid(H + dH, gn, cn) : std::numeric_limits<double>::infinity();
      if (std::isfinite(rn) && rn < st.residual) {
        accepted = true;
        H += dH;
        g = gn;
        c = cn;
        st.residual = rn;
        damping.good(theta);
      } else {
        p.set(y);
        damping.rejected(theta);
      }
    }
    ++st.iterations;
    summary.iterations += 1;
    if (!accepted) return st;
  }
}

#define BPDE_INSTANTIATE(Net) \
  template CorrectorStats AreaSolve<Net>::bordered_correct(double, double&, double, int);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
