// The vanishing Dirichlet regulariser (area_solve.h): from a critical point of F_1 = D_H, the
// critical points of F_ε = A_H + ε(D − A) = (1 − ε)A + εD + 2HV for ε → 0, each stage corrected
// from the Euler predictor along the ε-path, with a jump to ε = 0 once ε is small. F_ε is well
// conditioned in the tangential directions for ε > 0, where A_H alone is nearly singular.
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <algorithm>
#include <functional>
#include <cmath>
#include <string>

#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {

// A failed stage is retried with a ratio closer to 1 (√ of the last); successful ones square the
// ratio again (not below kSmallestEpsilonRatio). With V0 (the V form) the stages hold V = *V0 and
// move H, the predictor is the bordered one and the jump corrects with the bordered corrector; ε
// goes to 0 below kVolumeEpsilonFloor, and when the stages stop below kJumpFromEpsilon the last
// stage at ε = 0 is still tried.
template <class Net>
bool AreaSolve<Net>::homotopy(double& H, const StageFn& stage, std::string& note, const double* V0) {
  const bool fixed_volume = V0 != nullptr;
  double eps = 1.0, ratio = kFirstEpsilonRatio;
  int failures = 0;
  p.eps = eps;
  if (!stage(H, eps)) {
    note = "the start is not a critical point of D_H";
    return false;
  }
  // Progress (stage "cmc area"): the decades of ε removed, out of kProgressDecades; 1 at the end.
  p.progress_done = 0.0;
  report(o.progress, kAreaStage, 0, 1);
  while (true) {
    if (p.residual_at(H, 0.0) <= o.tolerance || eps == 0.0) break;
    double next = eps * ratio;
    if (next < (fixed_volume ? kVolumeEpsilonFloor : kEpsilonFloor)) next = 0.0;
    const Eigen::VectorXd y = p.get();
    const double Hs = H;
    predict(H, eps, next, fixed_volume);
    p.eps = next;
    if (stage(H, next)) {
      eps = next;
      ratio = std::max(ratio * ratio, kSmallestEpsilonRatio);
      p.progress_done =
          std::max(p.progress_done, eps > 0.0 ? std::min(0.999, std::log10(1.0 / eps) / kProgressDecades) : 0.999);
      report(o.progress, kAreaStage, p.progress_done, 1);
      if (eps <= kJumpFromEpsilon && p.residual_at(H, 0.0) > o.tolerance && jump(H, eps, V0)) {
        eps = 0.0;
        break;
      }
      continue;
    }
    p.set(y);
    H = Hs;
    p.eps = eps;
    ratio = std::sqrt(ratio);
    if (ratio > kLargestEpsilonRatio || ++failures > kMaxStageFailures) {
      // Keep the last stage: its first variation of A_H is ≈ ε |∇(D - A)| (reported by the
      // caller as a numerical limit when above the tolerance).
      note = "the Dirichlet regulariser could not be removed below ε = " + num(eps);
      if (fixed_volume && eps <= kJumpFromEpsilon) break;  // the V form tries the last stage below
      p.eps = 0.0;
      return eps <= kJumpFromEpsilon;
    }
  }
  p.eps = 0.0;
  if (p.residual_at(H, 0.0) <= o.tolerance || (fixed_volume && eps == 0.0)) return true;
  // The last stage at ε = 0, kept where it converges or lowers the first variation.
  const Eigen::VectorXd y = p.get();
  const double Hs = H, r0 = p.residual_at(H, 0.0);
  p.eps = eps;
  predict(H, eps, 0.0, fixed_volume);
  p.eps = 0.0;
  if (!stage(H, 0.0) && !(p.residual_at(H, 0.0) < r0)) {
    p.set(y);
    H = Hs;
  }
  if (p.residual_at(H, 0.0) > o.tolerance) note = "the last stage (ε = 0) stopped above the tolerance";
  return true;
}

// The predictor puts the start of the A_H corrector inside its basin, where the stages alone (no
// predictor) stopped at ε ≈ 1e-8 … 1e-6 with the first variation at 1e-9 … 1e-7. With V0 (the V
// form): the bordered predictor and corrector, which move H too (restored with the net when the
// jump is not kept).
template <class Net>
bool AreaSolve<Net>::jump(double& H, double eps, const double* V0) {
  const Eigen::VectorXd y = p.get();
  const double Hs = H;
  const std::shared_ptr<const AreaForm> a0 = p.a;
  predict(H, eps, 0.0, V0 != nullptr);
  p.eps = 0.0;
  choose_rule();
  CorrectorStats st;
  if (V0) {
    theta = kJumpDamping;
    st = bordered_correct(*V0, H, o.tolerance, kJumpIterations);
    st.iterations = 0;  // bordered_correct counts its own into summary
  } else if (o.solver == CmcSolver::Ceres) {
    CmcOptions co = o;
    co.max_corrector_iterations = kJumpIterations;
    st = ceres_correct(p, H, co);
  } else {
    double th = kJumpDamping;
    st = area_newton_correct(p, H, o, kJumpIterations, th, 0.0);
  }
  summary.iterations += st.iterations;
  if (st.ok) return true;
  p.set(y);
  H = Hs;
  p.eps = eps;
  p.a = a0;
  return false;
}

// dY/dε = −K_ε⁻¹ ∇(D − A) from the current point (a critical point of F_ε). With fixed_volume
// (the V form, H varies): from a critical point of F_ε + 2HV with V = V0, the bordered system
// [K_ε 2∇V; ∇Vᵀ 0][dY; dH] = [−∇(D − A); 0], and H moves too. Left unchanged when the predicted
// net is not regular.
template <class Net>
void AreaSolve<Net>::predict(double& H, double eps, double next, bool fixed_volume) {
  const Eigen::VectorXd y = p.get();
  const double e0 = p.eps;
  p.eps = eps;
  Eigen::VectorXd g1, g0;
  p.residual_at(H, 1.0, &g1);
  p.residual_at(H, 0.0, &g0);
  // One patch: dense LDLᵀ; a complex: the sparse factor (sparse_terms.h), LDLᵀ where K_ε is not
  // positive definite.
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> solve;
  Eigen::LDLT<Eigen::MatrixXd> f;
  SparseSymFactor fs;
  if (p.sparse) {
    fs.compute(p.hessian_sparse(H), /*ldlt_fallback=*/true);
    solve = [&](const Eigen::VectorXd& b) { return fs.solve(b); };
  } else {
    f.compute(p.hessian(H));
    solve = [&](const Eigen::VectorXd& b) { return Eigen::VectorXd(f.solve(b)); };
  }
  p.eps = e0;
  Eigen::VectorXd dy = -solve(g1 - g0);
  double dH = 0.0;
  if (fixed_volume) {
    const Eigen::VectorXd gV = p.volume_gradient(), b = solve(gV);
    const double den = gV.dot(b);
    if (!(std::abs(den) > 0) || !b.allFinite()) return;
    dH = gV.dot(dy) / (2.0 * den);
    dy -= 2.0 * dH * b;
  }
  if (!dy.allFinite()) return;
  p.set(y + (next - eps) * dy);
  if (!(p.a->min_normal(p.P()) > 0.0)) {
    p.set(y);
    return;
  }
  H += (next - eps) * dH;
}

template <class Net>
CmcOptions AreaSolve<Net>::stage_options(double e) const {
  CmcOptions so = o;
  so.tolerance = std::max(0.5 * o.tolerance, std::min(kStageToleranceCap, kStageToleranceFactor * e));
  return so;
}

#define BPDE_INSTANTIATE(Net)                                                                   \
  template bool AreaSolve<Net>::homotopy(double&, const StageFn&, std::string&, const double*); \
  template bool AreaSolve<Net>::jump(double&, double, const double*);                          \
  template void AreaSolve<Net>::predict(double&, double, double, bool);                        \
  template CmcOptions AreaSolve<Net>::stage_options(double) const;
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
