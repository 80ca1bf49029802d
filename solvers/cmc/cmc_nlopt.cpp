// NLopt correctors of the CMC solver (solvers/cmc/cmc.h):
//  - LD_LBFGS on D_H at fixed H (the branch point is a local minimum), in the variables Z with
//    Y = Y0 + L^{-T} Z, L the Cholesky factor of the free Dirichlet Gram (so D is 1/2|Z|^2 + ...).
//  - SLSQP for min D subject to V = V0 (isoperimetric view), same variables, then a bordered
//    Newton polish on (Y, H): [Hess D_H, 2∇V; ∇V^T, 0] (dY, dH) = -(∇D_H, V - V0).
#include <nlopt.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <string>

#include "bezierpde/solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {
namespace {

struct Precond {
  CmcProblem* p;
  const Eigen::MatrixXd* L;
  Eigen::VectorXd y0;

  // Y = Y0 + L^{-T} Z (per coordinate); y, z stored as 3k vectors (3a + c).
  Eigen::VectorXd to_y(const double* z) const {
    const int k = p->k();
    Eigen::MatrixX3d Z(k, 3);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < 3; ++c) Z(a, c) = z[3 * a + c];
    const Eigen::MatrixX3d Y = L->transpose().triangularView<Eigen::Upper>().solve(Z);
    Eigen::VectorXd y = y0;
    for (int a = 0; a < k; ++a) y.segment<3>(3 * a) += Y.row(a).transpose();
    return y;
  }
  // dF/dZ = L^{-1} dF/dY.
  void to_z_gradient(const Eigen::VectorXd& gy, double* gz) const {
    const int k = p->k();
    Eigen::MatrixX3d G(k, 3);
    for (int a = 0; a < k; ++a) G.row(a) = gy.segment<3>(3 * a).transpose();
    const Eigen::MatrixX3d Z = L->triangularView<Eigen::Lower>().solve(G);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < 3; ++c) gz[3 * a + c] = Z(a, c);
  }
};

struct LbfgsData {
  Precond pc;
  double H = 0, tol = 0;
  nlopt_opt opt = nullptr;
  bool reached = false;
  std::vector<double> z_best;
  int evals = 0;
};

double lbfgs_objective(unsigned n, const double* z, double* grad, void* data) {
  auto* d = static_cast<LbfgsData*>(data);
  ++d->evals;
  d->pc.p->set(d->pc.to_y(z));
  const double f = d->pc.p->value(d->H);
  if (!std::isfinite(f)) {
    nlopt_force_stop(d->opt);
    return std::numeric_limits<double>::max();
  }
  if (grad) {
    d->pc.to_z_gradient(d->pc.p->gradient(d->H), grad);
    if (d->pc.p->residual(d->H) <= d->tol) {
      d->reached = true;
      d->z_best.assign(z, z + n);
      nlopt_force_stop(d->opt);
    }
  }
  return f;
}

struct SlsqpData {
  Precond pc;
  double V0 = 0;
  int evals = 0;
};

double slsqp_objective(unsigned, const double* z, double* grad, void* data) {
  auto* d = static_cast<SlsqpData*>(data);
  ++d->evals;
  d->pc.p->set(d->pc.to_y(z));
  if (grad) d->pc.to_z_gradient(d->pc.p->gradient(0.0), grad);
  return d->pc.p->f->dirichlet(d->pc.p->P);
}

double slsqp_constraint(unsigned, const double* z, double* grad, void* data) {
  auto* d = static_cast<SlsqpData*>(data);
  d->pc.p->set(d->pc.to_y(z));
  if (grad) d->pc.to_z_gradient(d->pc.p->volume_gradient(), grad);
  return d->pc.p->f->volume(d->pc.p->P) - d->V0;
}

}  // namespace

CorrectorStats nlopt_correct(CmcProblem& p, double H, const CmcOptions& o, const Eigen::MatrixXd& L) {
  CorrectorStats st = start_stats(p, H, o);
  if (st.ok || !std::isfinite(st.residual)) return st;
  const unsigned n = static_cast<unsigned>(3 * p.k());
  LbfgsData d{Precond{&p, &L, p.get()}, H, o.tolerance, nullptr, false, {}, 0};
  nlopt_opt opt = nlopt_create(NLOPT_LD_LBFGS, n);
  d.opt = opt;
  nlopt_set_min_objective(opt, lbfgs_objective, &d);
  nlopt_set_ftol_rel(opt, 1e-16);
  nlopt_set_xtol_rel(opt, 0.0);
  nlopt_set_maxeval(opt, 50 * o.max_corrector_iterations);
  nlopt_set_vector_storage(opt, 20);
  std::vector<double> z(n, 0.0);
  double f = 0;
  nlopt_optimize(opt, z.data(), &f);
  nlopt_destroy(opt);
  st.iterations = d.evals;
  if (d.reached) z = d.z_best;
  const Eigen::VectorXd y = d.pc.to_y(z.data());
  if (!y.allFinite()) return st;
  p.set(y);
  st.residual = p.residual(H);
  if (st.residual <= o.tolerance) {
    st.ok = true;
    return st;
  }
  // L-BFGS stops where D_H is flat to rounding (~1e-8..1e-10 relative in the gradient): polish.
  const CorrectorStats pol = newton_correct(p, H, o, 3);
  st.polish_steps = pol.iterations;
  st.residual = pol.residual;
  st.ok = pol.ok;
  st.pd = pol.pd;
  return st;
}

CorrectorStats nlopt_volume_solve(CmcProblem& p, double V0, const CmcOptions& o, const Eigen::MatrixXd& L, double& H,
                                  std::string& note) {
  CorrectorStats st;
  const unsigned n = static_cast<unsigned>(3 * p.k());
  SlsqpData d{Precond{&p, &L, p.get()}, V0, 0};
  const double vscale = std::max(p.f->volume_form().value_scale(p.P), std::abs(V0));
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, n);
  nlopt_set_min_objective(opt, slsqp_objective, &d);
  nlopt_add_equality_constraint(opt, slsqp_constraint, &d, 1e-13 * std::max(vscale, 1e-300));
  nlopt_set_ftol_rel(opt, 1e-15);
  nlopt_set_xtol_rel(opt, 1e-13);
  nlopt_set_maxeval(opt, 100 * o.max_corrector_iterations);
  std::vector<double> z(n, 0.0);
  double f = 0;
  const nlopt_result code = nlopt_optimize(opt, z.data(), &f);
  nlopt_destroy(opt);
  st.iterations = d.evals;
  Eigen::VectorXd y = d.pc.to_y(z.data());
  if (!y.allFinite()) {
    note = "SLSQP failed (NLopt code " + std::to_string(static_cast<int>(code)) + ")";
    return st;
  }
  p.set(y);
  H = multiplier(p);
  // Bordered Newton polish on (y, H).
  const int k3 = static_cast<int>(n);
  auto vres = [&]() {
    const double vs = std::max(p.f->volume_form().value_scale(p.P), std::abs(V0));
    return std::abs(p.f->volume(p.P) - V0) / std::max(vs, 1e-300);
  };
  for (int it = 0; it <= 10; ++it) {
    st.residual = p.residual(H);
    const double rv = vres();
    if (std::isfinite(st.residual) && st.residual <= o.tolerance && rv <= o.tolerance) {
      st.ok = true;
      break;
    }
    if (it == 10 || !std::isfinite(st.residual)) break;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(k3 + 1, k3 + 1);
    const Eigen::VectorXd gV = p.volume_gradient();
    K.topLeftCorner(k3, k3) = p.hessian(H);
    K.block(0, k3, k3, 1) = 2.0 * gV;
    K.block(k3, 0, 1, k3) = gV.transpose();
    Eigen::VectorXd rhs(k3 + 1);
    rhs.head(k3) = -p.gradient(H);
    rhs(k3) = -(p.f->volume(p.P) - V0);
    const Eigen::VectorXd dx = K.partialPivLu().solve(rhs);
    if (!dx.allFinite()) break;
    p.set(p.get() + dx.head(k3));
    H += dx(k3);
    ++st.polish_steps;
  }
  // Report the multiplier exactly as FORMATS.md defines it (equal to the Newton H at convergence).
  H = multiplier(p);
  st.residual = p.residual(H);
  st.ok = st.ok && std::isfinite(st.residual) && st.residual <= o.tolerance && vres() <= o.tolerance;
  note = st.ok ? "min D subject to V = V0 by NLopt SLSQP (" + std::to_string(d.evals) + " evaluations, NLopt code " +
                     std::to_string(static_cast<int>(code)) + ") + " + std::to_string(st.polish_steps) +
                     " bordered Newton polish step(s)"
               : "SLSQP did not reach a critical point of D with V = V0 (NLopt code " +
                     std::to_string(static_cast<int>(code)) + ")";
  return st;
}

}  // namespace bpde::cmc_detail
