// AreaSolve's shared steps (area_solve.h): the Dirichlet start it caches, the quadrature rules,
// saved states, the residuals the driver compares routes by, the stability test and the gate of
// mean-curvature-start.
#include "bezierpde/solvers/cmc/area/area_solve.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

namespace bpde::cmc_detail::area_impl {

template <class Net>
const CmcResult<Net>& AreaSolve<Net>::dirichlet_solution(double H, const double* V0) {
  const std::pair<double, std::optional<double>> key{H, V0 ? std::optional<double>(*V0) : std::nullopt};
  if (!dirichlet_cache || dirichlet_cache->first != key) {
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    od.solver = V0 ? CmcSolver::NLopt : CmcSolver::Newton;
    od.H = H;
    od.V = key.second;
    dirichlet_cache.emplace(key, solve_cmc(data, od));
  }
  return dirichlet_cache->second;
}

// Circle n = 16: the D_H start needs q = 27 for 1e-12, the final net q = 20, so each ε-stage
// chooses its own rule (the early stages need far fewer nodes; the Hessian's cost is linear in
// the nodes), and the final rule check refines on the final net where needed.
template <class Net>
bool AreaSolve<Net>::choose_rule_for(double tol, int start_q, int start_grading, int start_levels) {
  const AreaRule r = choose_area_rule(tri, n, m, p.P(), p.base.free, kRuleToleranceFactor * tol, start_q,
                                      start_grading, start_levels, p.base.f->assembly());
  p.a = r.form;
  rule_change = r.change;
  return r.ok;
}

template <class Net>
bool AreaSolve<Net>::refine_rule() {
  const std::shared_ptr<const AreaForm> a = p.a;
  return choose_rule(a->points_per_direction(), a->grading(), a->levels());
}

template <class Net>
bool AreaSolve<Net>::at(const SoftEndMark& mark) const {
  return !o.V && mark.kind != SoftModeEnd::None && mark.a == p.a && p.eps == 0.0 && mark.P.rows() == p.P().rows() &&
         mark.P == p.P();
}

template <class Net>
SoftModeEnd AreaSolve<Net>::soft_end() const {
  if (at(degenerate_end)) return SoftModeEnd::DegenerateBound;
  if (at(stationary_end)) return SoftModeEnd::Stationary;
  return SoftModeEnd::None;
}

template <class Net>
std::string AreaSolve<Net>::soft_verdict(bool long_form) const {
  std::string v;
  if (at(stationary_end))
    v = long_form ? "; no step over the soft (tangential) modes lowers it (a stationary point of its norm there, "
                    "not a critical point of A_H)"
                  : ", where no step over the soft (tangential) modes lowers it";
  if (at(degenerate_end))
    v += "; the trust-region descent on A_H from there heads for a degenerate parametrisation (|x_u ∧ x_v| "
         "below a quarter of its smallest value at the start), so the net is the one it started from";
  return v;
}

template <class Net>
typename AreaSolve<Net>::State AreaSolve<Net>::save() const {
  return {p.base.P, p.a, theta, rule_change, p.eps, stationary_end, degenerate_end};
}

template <class Net>
void AreaSolve<Net>::restore(const State& s) {
  p.base.P = s.P;
  p.a = s.a;
  theta = s.theta;
  rule_change = s.rule_change;
  p.eps = s.eps;
  stationary_end = s.stationary_end;
  degenerate_end = s.degenerate_end;
}

template <class Net>
double AreaSolve<Net>::checked_residual(double H) {
  const std::shared_ptr<const AreaForm> a = p.a;
  const double change = rule_change;
  refine_rule();
  const double r = o.V ? vresidual(*o.V, H) : p.residual_at(H, 0.0);
  p.a = a;
  rule_change = change;
  return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
}

template <class Net>
double AreaSolve<Net>::vresidual(double V0, double H) const {
  const double vs = p.base.f->volume_form().value_scale(p.P());
  return std::max(p.residual_at(H, 0.0), std::abs(p.base.f->volume(p.P()) - V0) / (vs > 0 ? vs : 1.0));
}

// σ = kStrictMinimumShift × max_i K_ii / C_ii is a Rayleigh quotient, so at most the largest
// eigenvalue of K v = λ C v. The nearly singular tangential modes are not all positive: on the
// circle at n = 6 the two softest are −1.0e-8 and −0.9e-8 of C (λ_max 1.31) all along the branch
// from H = −0.62 on; at n = 10 about 20 soft modes lie at −6e-9 … −2e-12 λ_max. A fold is where a
// mode of the surface's normal motion crosses 0; past it the corrector finds no point.
template <class Net>
bool AreaSolve<Net>::strict_minimum(double H, Eigen::VectorXd* tangent) {
  if (p.sparse) {  // a complex: the same test by the sparse factor
    Eigen::SparseMatrix<double> K = p.hessian_sparse(H);
    if (!Eigen::Map<const Eigen::VectorXd>(K.valuePtr(), K.nonZeros()).allFinite()) return false;
    const Eigen::VectorXd d = K.diagonal().cwiseQuotient(Eigen::VectorXd(p.sparse_C().diagonal()));
    const double scale = d.maxCoeff();
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    SparseSymFactor f;
    if (!f.compute(K + kStrictMinimumShift * scale * p.sparse_C())) return false;
    if (tangent) *tangent = -2.0 * f.solve(p.volume_gradient());
    return true;
  }
  Eigen::MatrixXd K = p.hessian(H);
  if (!K.allFinite()) return false;
  const double scale = K.diagonal().cwiseQuotient(p.dense_C().diagonal()).maxCoeff();  // C's diagonal > 0 (a Gram)
  if (!(scale > 0) || !std::isfinite(scale)) return false;
  K += kStrictMinimumShift * scale * p.dense_C();
  Eigen::LLT<Eigen::MatrixXd> llt(K);
  if (llt.info() != Eigen::Success) return false;
  if (tangent) *tangent = -2.0 * llt.solve(p.volume_gradient());
  return true;
}

// On conformal data the D_H point is already a critical point of A_H to within the degree (the
// conformal sphere triangle: 8.2e-7, 3.6e-8, 1.6e-9, 6.5e-11 at n = 10, 12, 14, 16); from n = 12
// on the Dirichlet routes converge from it in one iteration, where the least squares of
// mean-curvature-start cost up to 0.3 s. Leaves the net and the rule as they were.
template <class Net>
double AreaSolve<Net>::dirichlet_first_variation(const double* V0) {
  const CmcResult<Net>& d = dirichlet_solution(o.H, V0);  // the cached start, not a copy
  if (!d.summary.converged) return std::numeric_limits<double>::infinity();
  const Eigen::MatrixX3d P0 = p.base.P;
  const std::shared_ptr<const AreaForm> a0 = p.a;
  const double change0 = rule_change;
  p.base.P = d.net.points();
  choose_rule_for(kConformalFirstVariation);
  const double r = p.residual_at(V0 ? d.H : o.H, 0.0);
  p.base.P = P0;
  p.a = a0;
  rule_change = change0;
  return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
}

#define BPDE_INSTANTIATE(Net)                                                                             \
  template const CmcResult<Net>& AreaSolve<Net>::dirichlet_solution(double, const double*);              \
  template bool AreaSolve<Net>::choose_rule_for(double, int, int, int);                                  \
  template bool AreaSolve<Net>::refine_rule();                                                           \
  template bool AreaSolve<Net>::at(const SoftEndMark&) const;                                            \
  template SoftModeEnd AreaSolve<Net>::soft_end() const;                                                 \
  template std::string AreaSolve<Net>::soft_verdict(bool) const;                                         \
  template AreaSolve<Net>::State AreaSolve<Net>::save() const;                                           \
  template void AreaSolve<Net>::restore(const State&);                                                   \
  template double AreaSolve<Net>::checked_residual(double);                                              \
  template double AreaSolve<Net>::vresidual(double, double) const;                                       \
  template bool AreaSolve<Net>::strict_minimum(double, Eigen::VectorXd*);                                \
  template double AreaSolve<Net>::dirichlet_first_variation(const double*);
BPDE_INSTANTIATE(TriangularNet)
BPDE_INSTANTIATE(TensorNet)
BPDE_INSTANTIATE(ComplexNet)

}  // namespace bpde::cmc_detail::area_impl
