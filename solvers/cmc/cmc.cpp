#include "bezierpde/solvers/cmc/cmc.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/complex_net.h"
#include "bezierpde/solvers/summary.h"

namespace bpde {

void CmcOptions::validate() const {
  if (!std::isfinite(H)) throw NonFiniteError("cmc: H must be a finite number");
  if (V && !std::isfinite(*V)) throw NonFiniteError("cmc: V must be a finite number");
  check_fixed_set_and_method(cmc_requirements(functional, V.has_value()), fixed, to_string(solver), "cmc");
  if (!(tolerance > 0.0 && tolerance <= 1e-3)) throw ParameterError("cmc: tolerance must be in (0, 1e-3]");
  if (!mean_curvature_tolerance_in_range(mean_curvature_tolerance))
    throw ParameterError("cmc: mean_curvature_tolerance must be in (0, 1)");
  if (max_least_squares_iterations < 1) throw ParameterError("cmc: max_least_squares_iterations must be >= 1");
  if (max_corrector_iterations < 1) throw ParameterError("cmc: max_corrector_iterations must be >= 1");
  if (max_continuation_steps < 1) throw ParameterError("cmc: max_continuation_steps must be >= 1");
  if (!(min_step > 0.0 && min_step < 1.0)) throw ParameterError("cmc: min_step must be in (0, 1)");
}

namespace cmc_detail {

Eigen::VectorXd CmcProblem::get() const {
  Eigen::VectorXd y(3 * k());
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(y.data(), k(), 3) = P(free, Eigen::all);
  return y;
}

void CmcProblem::set(const Eigen::VectorXd& y) {
  P(free, Eigen::all) = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(y.data(), k(), 3);
}

Eigen::VectorXd CmcProblem::gradient(double H) const {
  const Eigen::MatrixX3d G = f->gradient_rows(P, H, free);
  Eigen::VectorXd g(3 * k());
  for (int a = 0; a < k(); ++a) g.segment<3>(3 * a) = G.row(a).transpose();
  return g;
}

Eigen::VectorXd CmcProblem::volume_gradient() const {
  const Eigen::MatrixX3d G = f->volume_form().gradient_rows(P, free);
  Eigen::VectorXd g(3 * k());
  for (int a = 0; a < k(); ++a) g.segment<3>(3 * a) = G.row(a).transpose();
  return g;
}

double CmcProblem::evaluate(double H, Eigen::VectorXd& g, double tolerance, double scale_hint, double* scale) const {
  Eigen::MatrixX3d F;
  double r = 0.0;
  bool done = false;
  if (scale_hint > 0.0) {
    F = f->gradient_rows(P, H, free);
    const double num = F.size() ? F.cwiseAbs().maxCoeff() : 0.0;
    if (!std::isfinite(num) || num > 1e3 * tolerance * scale_hint) {
      r = std::isfinite(num) ? num / scale_hint : std::numeric_limits<double>::infinity();
      if (scale) *scale = scale_hint;
      done = true;
    }
  }
  if (!done) r = f->residual(P, H, free, &F, scale);
  g.resize(3 * k());
  for (int a = 0; a < k(); ++a) g.segment<3>(3 * a) = F.row(a).transpose();
  return r;
}

double multiplier(const CmcProblem& p) {
  const Eigen::VectorXd gD = p.gradient(0.0);
  const Eigen::VectorXd gV = p.volume_gradient();
  const double nv = gV.squaredNorm();
  if (nv == 0.0) return 0.0;
  return -gD.dot(gV) / (2.0 * nv);
}

CorrectorStats newton_correct(CmcProblem& p, double H, const CmcOptions& o, int max_iterations) {
  // Newton with the exact Hessian, reusing its factorisation while the residual falls fast
  // (ratio <= 1/100 per step); refactorised otherwise. Fails when a step with a fresh factorisation
  // does not reduce the residual (from the third iterate on), or when it is not finite.
  CorrectorStats st;
  double prev_r = std::numeric_limits<double>::infinity();
  Eigen::VectorXd g;
  double scale = 0.0;
  std::unique_ptr<SymFactor> fac;
  bool fresh = false;
  for (int it = 0;; ++it) {
    st.residual = p.evaluate(H, g, o.tolerance, scale, &scale);
    if (!std::isfinite(st.residual)) return st;
    if (st.residual <= o.tolerance) {
      st.ok = true;
      return st;
    }
    if (it >= max_iterations) return st;
    const bool slow = st.residual > prev_r / 100;
    if (slow && fresh && it >= 2 && st.residual > prev_r) return st;  // Newton itself diverges
    if (!fac || slow) {
      fac = std::make_unique<SymFactor>(p.hessian(H));
      st.pd = fac->positive_definite() ? 1 : 0;
      fresh = true;
    } else {
      fresh = false;
    }
    prev_r = st.residual;
    const Eigen::VectorXd dx = -fac->solve(g);
    if (!dx.allFinite()) return st;
    p.set(p.get() + dx);
    ++st.iterations;
  }
}

std::string fold_message(double h, bool gram_singular) {
  const std::string buf = num(h);
  if (gram_singular)
    return std::string("numerical limit: continuation stopped at H ≈ ") + buf +
           ": the Dirichlet Gram over the free points is numerically singular at this degree "
           "(Bernstein conditioning grows like 4^n), so eq. (11) cannot be resolved to the "
           "tolerance; use a lower degree";
  return std::string("no critical point on the branch from H = 0 beyond H ≈ ") + buf;
}

void check_degree(const TriangularNet& net, FixedSet fixed) {
  const int need = fixed == FixedSet::BoundaryAdjacent ? 6 : 3;
  if (fixed == FixedSet::UBoundaries)
    throw UnsupportedProblem("cmc: fixed \"u-boundaries\" is defined for tensor nets only");
  if (net.n() < need)
    throw DegreeError("cmc: a triangular net with " + to_string(fixed) +
                      " data needs degree >= " + std::to_string(need) + " (got " + std::to_string(net.n()) + ")");
}

void check_degree(const TensorNet& net, FixedSet fixed) {
  const int need = fixed == FixedSet::BoundaryAdjacent ? 4 : 2;
  if (net.n() < need || (fixed != FixedSet::UBoundaries && net.m() < need))
    throw DegreeError("cmc: a tensor net with " + to_string(fixed) + " data needs degree >= " + std::to_string(need) +
                      " in each direction (got " + std::to_string(net.n()) + ", " + std::to_string(net.m()) + ")");
}

std::shared_ptr<const CmcFunctional> functional_for(const TriangularNet& net) {
  return CmcFunctional::cached_triangular(net.n());
}
std::shared_ptr<const CmcFunctional> functional_for(const TensorNet& net) {
  return CmcFunctional::cached_tensor(net.n(), net.m());
}

namespace {

// A Cholesky factor of the free Gram C_ff, shifted by up to 1e-2 of its diagonal where rounding
// makes it indefinite; the identity where even that fails.
Eigen::MatrixXd shifted_cholesky(const Eigen::MatrixXd& Cff) {
  const Eigen::Index k = Cff.rows();
  const double d = k ? Cff.diagonal().cwiseAbs().maxCoeff() : 1.0;
  for (double shift = 1e-14; shift < 1e-2; shift *= 10) {
    Eigen::LLT<Eigen::MatrixXd> llt(Cff + shift * d * Eigen::MatrixXd::Identity(k, k));
    if (llt.info() == Eigen::Success) return llt.matrixL();
  }
  return Eigen::MatrixXd::Identity(k, k);
}

}  // namespace

DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx) {
  const Eigen::MatrixXd& C = p.f->gram();
  const Eigen::MatrixXd Cff = C(p.free, p.free), Cfx = C(p.free, fixed_idx);
  const Eigen::MatrixX3d Px = p.P(fixed_idx, Eigen::all);
  DirichletFactor f;
  f.gram = std::make_unique<SymFactor>(Cff);
  const Eigen::MatrixX3d Y = -f.gram->solve(Cfx * Px);
  p.P(p.free, Eigen::all) = Y;
  f.L = f.gram->cholesky() ? Eigen::MatrixXd(f.gram->matrixL()) : shifted_cholesky(Cff);
  return f;
}

Eigen::MatrixX3d DirichletFactor::solve(const Eigen::MatrixX3d& B) const {
  if (!sparse) return gram->solve(B);
  Eigen::MatrixX3d X(B.rows(), 3);
  for (int c = 0; c < 3; ++c) X.col(c) = sparse->solve(B.col(c));
  return X;
}

const Eigen::MatrixXd& preconditioner(DirichletFactor& f, const CmcProblem& p) {
  if (f.L.size() == 0 && p.k() > 0) {
    const Eigen::MatrixXd Cff = p.f->gram()(p.free, p.free);
    Eigen::LLT<Eigen::MatrixXd> llt(Cff);
    f.L = llt.info() == Eigen::Success ? Eigen::MatrixXd(llt.matrixL()) : shifted_cholesky(Cff);
  }
  return f.L;
}

TriangularNet make_net(const TriangularNet& data, const Eigen::MatrixX3d& P) {
  return TriangularNet(data.n(), P);
}
TensorNet make_net(const TensorNet& data, const Eigen::MatrixX3d& P) {
  return TensorNet(data.n(), data.m(), P);
}

namespace {

// How a solve ended, before the final checks of finish().
struct Outcome {
  double H = 0.0;  ///< H of the net in p.P
  bool ok = false;
  Status why = Status::NoConvergence;  ///< the reason when !ok
  std::string message;
  /// Eq. (11)'s residual at p.P and H as CmcFunctional::residual computes it, where the corrector
  /// that ended there computed it (NaN: finish() computes it).
  double residual = std::numeric_limits<double>::quiet_NaN();
};

// The result from p.P at out.H. Never reports a net as converged unless eq. (11) holds to the
// tolerance here.
template <class Net>
void finish(CmcResult<Net>& res, const Net& data, const CmcProblem& p, const CmcOptions& o, Outcome out) {
  res.H = out.H;
  res.D = p.f->dirichlet(p.P);
  res.V = p.f->volume(p.P);
  res.DH = res.D + 2.0 * out.H * res.V;
  res.energy = res.DH;
  res.A = area(make_net(data, p.P));
  res.net = make_net(data, p.P);
  res.summary.residual = std::isnan(out.residual) ? p.residual(out.H) : out.residual;
  if (out.ok && !(res.summary.residual <= o.tolerance)) {
    out.ok = false;
    out.why = Status::NumericalLimit;
    out.message = "the final net misses eq. (11) by " + std::to_string(res.summary.residual) +
                  " (relative) after: " + out.message;
  }
  if (out.ok) {
    res.summary.message = std::move(out.message);
    res.summary.set_converged();
  } else {
    res.summary.set_failed(out.why, std::move(out.message));
  }
}

// V mode: min D subject to V = V0 from the Dirichlet extremal in p.P.
Outcome volume_solve(CmcProblem& p, const CmcOptions& o, const Eigen::MatrixXd& L, Summary& summary) {
  Outcome out;
  const CorrectorStats st = nlopt_volume_solve(p, *o.V, o, L, out.H, out.message);
  summary.iterations = st.iterations + st.polish_steps;
  out.ok = st.ok;
  return out;
}

// H = 0: the Dirichlet extremal in p.P is the answer.
Outcome dirichlet_outcome(const CmcProblem& p, const CmcOptions& o) {
  const double r = p.residual(0.0);
  if (r <= o.tolerance) return {0.0, true, Status::Converged, "Dirichlet extremal (linear solve)"};
  return {0.0, false, Status::NumericalLimit, "Dirichlet extremal: the linear solve is not accurate to the tolerance"};
}

// The free rows of ∇V at the points P, as a 3k vector (CmcProblem's order).
Eigen::VectorXd volume_gradient_at(const CmcProblem& p, const Eigen::MatrixX3d& P) {
  const Eigen::MatrixX3d G = p.f->volume_form().gradient_rows(P, p.free);
  Eigen::VectorXd g(3 * p.k());
  for (int a = 0; a < p.k(); ++a) g.segment<3>(3 * a) = G.row(a).transpose();
  return g;
}

}  // namespace

// The Taylor series of the branch at a branch point (H0, P_0 = p.P): P(H0 + s) = Σ_m P_m s^m, the
// coefficients m = 1 … kBranchSeriesOrder over the free points. Eq. (11) is C P + 2H g(P) = 0 over the
// free rows with g = ∇V, a homogeneous quadratic form in all the points, g(P) = Q(P, P) with Q
// symmetric bilinear; its s^m coefficient gives
//   K P_m = -2 (H0 S'_m + S_{m-1}),  S_j = Σ_{a+b=j} Q(P_a, P_b),  S'_m = the same over a, b >= 1,
// with K = C + 2H0 g'(P_0) the Hessian of D_H at the point. Q comes from g exactly:
// 2Q(A, B) = g(A + B) - g(A) - g(B). Order 4 takes 7 evaluations of g at H0 = 0 (9 elsewhere) and
// 4 solves with K; on the sphere's data at H = 1 in one step it leaves eq. (11) at 5e-4 instead of
// 1e-2 (the tangent), so that Newton (and Ceres's Levenberg–Marquardt) needs one step fewer.
std::vector<Eigen::VectorXd> branch_series(const CmcProblem& p, double H0, const Eigen::VectorXd& g0,
                                           const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& solve_K) {
  const int order = kBranchSeriesOrder;
  std::vector<Eigen::VectorXd> y(order + 1), G(order + 1);  // y[m]: P_m's free rows; G[m] = g(P_m)
  auto free_only = [&](const Eigen::VectorXd& v) {
    Eigen::MatrixX3d X = Eigen::MatrixX3d::Zero(p.P.rows(), 3);
    X(p.free, Eigen::all) = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(v.data(), p.k(), 3);
    return X;
  };
  auto g_of = [&](const Eigen::VectorXd& v) { return volume_gradient_at(p, free_only(v)); };
  // 2Q(P_0, P_a) and 2Q(P_a, P_b), a, b >= 1.
  auto q0 = [&](int a) { return Eigen::VectorXd(volume_gradient_at(p, p.P + free_only(y[a])) - g0 - G[a]); };
  auto qab = [&](int a, int b) { return Eigen::VectorXd(g_of(y[a] + y[b]) - G[a] - G[b]); };
  // S'_m over the pairs a + b = m, a, b >= 1.
  auto inner = [&](int m) {
    Eigen::VectorXd S = Eigen::VectorXd::Zero(3 * p.k());
    for (int a = 1; 2 * a < m; ++a) S += qab(a, m - a);
    if (m % 2 == 0) S += G[m / 2];
    return S;
  };
  Eigen::VectorXd S_prev = g0;  // S_0
  std::vector<Eigen::VectorXd> out;
  for (int m = 1; m <= order; ++m) {
    const Eigen::VectorXd Sm = inner(m);  // S'_m (zero for m = 1)
    y[m] = -2.0 * solve_K(S_prev + H0 * Sm);
    if (!y[m].allFinite()) break;
    out.push_back(y[m]);
    if (m == order) break;
    G[m] = g_of(y[m]);
    S_prev = q0(m) + Sm;  // S_m
  }
  return out;
}

// The series summed at the step s: the terms while they fall (beyond the series' radius a term
// that grows is left out, and so are the ones after it).
Eigen::VectorXd branch_prediction(const Eigen::VectorXd& y, const std::vector<Eigen::VectorXd>& series, double s) {
  Eigen::VectorXd pred = y;
  double sp = 1.0, last = std::numeric_limits<double>::infinity();
  for (const Eigen::VectorXd& c : series) {
    sp *= s;
    const double size = std::abs(sp) * c.norm();
    if (!(size < last)) break;
    pred += sp * c;
    last = size;
  }
  return pred;
}

namespace {

}  // namespace

// First step: the whole way to Ht, but not beyond |H| = 16 / (size of the data), the scale where
// a fold can occur (steps double after easy corrector runs, so large |H| are reached quickly).
double first_step(double Ht, const Eigen::MatrixX3d& P, const std::vector<int>& fixed_idx) {
  double step = Ht;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int r : fixed_idx) {
    lo = lo.cwiseMin(P.row(r).transpose());
    hi = hi.cwiseMax(P.row(r).transpose());
  }
  const double diam = (hi - lo).norm();
  if (std::isfinite(diam) && diam > 0 && std::abs(step) > 16.0 / diam) step = std::copysign(16.0 / diam, Ht);
  return step;
}

namespace {

// The chosen corrector at fixed H from the predicted point in p.P.
CorrectorStats correct(CmcProblem& p, double H, const CmcOptions& o, const Eigen::MatrixXd& L) {
  switch (o.solver) {
    case CmcSolver::Newton:
      return newton_correct(p, H, o, o.max_corrector_iterations);
    case CmcSolver::Ceres:
      return ceres_correct(p, H, o);
    case CmcSolver::NLopt:
      return nlopt_correct(p, H, o, L);
  }
  return {};
}

}  // namespace

// Stay on the branch: the corrector may move the predicted point by at most half the step (the
// series predictor is at least second-order accurate, so small steps always pass on the branch).
bool on_branch(const Eigen::VectorXd& y, const Eigen::VectorXd& pred, const Eigen::VectorXd& yn) {
  const double dev = (yn - pred).norm(), move = (yn - y).norm();
  return dev <= 0.5 * move + 1e-12 * std::max(1.0, y.norm());
}

namespace {

// Positive definite Hessian at H (strict local minimum: still before the first fold); known from
// the corrector when corrector_pd == 1. When the continuation goes on (!last), the factor also
// gives the branch's series there (branch_series; its first term the tangent dY/dH = -J^{-1} 2 dV/dY).
bool strict_minimum(const CmcProblem& p, double H, bool last, int corrector_pd, std::vector<Eigen::VectorXd>& next_series) {
  if (last && corrector_pd == 1) return true;
  const SymFactor fac(p.hessian(H));
  if (fac.positive_definite() && !last)
    next_series = branch_series(p, H, p.volume_gradient(), [&](const Eigen::VectorXd& b) { return fac.solve(b); });
  return fac.positive_definite();
}

// H mode, H != 0: continuation from the Dirichlet extremal in p.P to o.H. Predictor: the branch's
// Taylor series (branch_series);
// corrector: the chosen solver; a step is accepted when the corrector converged, stayed on the
// branch and the Hessian is positive definite. Adds the corrector iterations to summary.
Outcome continue_branch(CmcProblem& p, const CmcOptions& o, DirichletFactor& dir,
                        const std::vector<int>& fixed_idx, Summary& summary, int& continuation_steps) {
  const double Ht = o.H;
  const bool gram_singular = !dir.cholesky();
  // At H = 0 the Hessian is the Gram: the series from the Dirichlet factor.
  std::vector<Eigen::VectorXd> series = branch_series(p, 0.0, p.volume_gradient(), [&](const Eigen::VectorXd& b) {
    const Eigen::MatrixX3d X = dir.solve(Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(b.data(), p.k(), 3));
    Eigen::VectorXd x(b.size());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(x.data(), p.k(), 3) = X;
    return x;
  });
  const Eigen::MatrixXd& L = o.solver == CmcSolver::NLopt ? preconditioner(dir, p) : dir.L;
  Eigen::VectorXd y = p.get();
  StepController control(Ht, first_step(Ht, p.P, fixed_idx), o);
  int polish = 0;
  double final_residual = std::numeric_limits<double>::quiet_NaN();  // the corrector's, at the last point accepted
  while (!control.reached_target()) {
    if (!control.attempt()) {
      p.set(y);
      return {control.h(), false, Status::NoConvergence,
              "continuation stopped at H ≈ " + num(control.h()) + " after max_continuation_steps = " +
                  std::to_string(o.max_continuation_steps) + " attempts, before reaching H = " + std::to_string(Ht) +
                  " (no fold was detected; raise max_continuation_steps)"};
    }
    const StepController::Step step = control.propose();
    const bool last = step.hn == Ht;
    const Eigen::VectorXd pred = branch_prediction(y, series, step.s);
    p.set(pred);
    const CorrectorStats st = correct(p, step.hn, o, L);
    summary.iterations += st.iterations + st.polish_steps;
    std::vector<Eigen::VectorXd> next_series;
    if (st.ok && on_branch(y, pred, p.get()) && strict_minimum(p, step.hn, last, st.pd, next_series)) {
      polish += st.polish_steps;
      y = p.get();
      final_residual = st.residual;
      if (!last) series = std::move(next_series);
      ++continuation_steps;
      control.accept(step, st.iterations);
      report(o.progress, "cmc continuation", std::abs(control.h()), std::abs(Ht));
    } else {
      p.set(y);
      if (!control.reject(step))
        return {control.h(), false, gram_singular ? Status::NumericalLimit : Status::Fold,
                fold_message(control.h(), gram_singular)};
    }
  }
  std::string msg = "reached H = " + std::to_string(Ht) + " in " + std::to_string(continuation_steps) +
                    " continuation step(s) with " + to_string(o.solver);
  if (polish > 0) msg += " (+" + std::to_string(polish) + " Newton polish step(s))";
  return {Ht, true, Status::Converged, msg, final_residual};
}

template <class Net>
CmcResult<Net> solve_impl(const Net& data, const CmcOptions& o) {
  if (o.functional == CmcFunctionalKind::Area) return solve_area(data, o);
  if (o.functional == CmcFunctionalKind::MeanCurvature) return solve_mean_curvature(data, o);
  CmcResult<Net> res;
  {
    ScopedTimer timer(res.summary.seconds);
    DirichletStart start = dirichlet_start(data, o);
    CmcProblem& p = start.p;
    const std::vector<int>& fixed_idx = start.fixed_idx;
    DirichletFactor& dir = start.dir;
    const Outcome out = o.V          ? volume_solve(p, o, preconditioner(dir, p), res.summary)
                        : o.H == 0.0 ? dirichlet_outcome(p, o)
                                     : continue_branch(p, o, dir, fixed_idx, res.summary, res.continuation_steps);
    finish(res, data, p, o, out);
  }
  return res;
}

template <class Net>
Net dirichlet_impl(const Net& data, FixedSet fixed) {
  check_degree(data, fixed);
  const std::vector<int> fixed_idx = data.fixed_indices(fixed);
  CmcProblem p{functional_for(data), data.free_indices(fixed), data.points()};
  dirichlet_solve(p, fixed_idx);
  return make_net(data, p.P);
}

// Control points beyond this size leave no usable surface: the report's sampling and checks
// square and sum coordinates, which overflow near 1e154.
constexpr double kLargestUsableCoordinate = 1e150;

// A solve that ran out of the range of double (a volume far beyond what the boundary can enclose,
// e.g. V = 1e200) is not a result: the data net is returned instead, with converged false and a
// message that says where the control points went (exit 1, never a mesh of infinities).
template <class Net>
CmcResult<Net> in_range(CmcResult<Net> res, const Net& data) {
  const double largest = res.net.points().size() ? res.net.points().cwiseAbs().maxCoeff() : 0.0;
  if (std::isfinite(largest) && largest <= kLargestUsableCoordinate) return res;
  res.summary.converged = false;
  res.summary.status = Status::NoConvergence;
  res.summary.message = "the solve left the range of double: a control point reached |x| = " +
                        (std::isfinite(largest) ? num(largest, 3) : std::string("inf or nan")) +
                        " (the data net is returned; " + res.summary.message + ")";
  res.net = data;
  // the figures belonged to the net that left the range: none (null in result.json)
  res.D = res.V = res.DH = res.A = res.energy = std::numeric_limits<double>::quiet_NaN();
  return res;
}

}  // namespace
}  // namespace cmc_detail

CmcResult<TriangularNet> solve_cmc(const TriangularNet& data, const CmcOptions& options) {
  return cmc_detail::in_range(cmc_detail::solve_impl(data, options), data);
}
CmcResult<TensorNet> solve_cmc(const TensorNet& data, const CmcOptions& options) {
  return cmc_detail::in_range(cmc_detail::solve_impl(data, options), data);
}
CmcResult<ComplexNet> solve_cmc(const ComplexNet& data, const CmcOptions& options) {
  return cmc_detail::in_range(cmc_detail::solve_impl(data, options), data);
}
TriangularNet dirichlet_extremal(const TriangularNet& data, FixedSet fixed) {
  return cmc_detail::dirichlet_impl(data, fixed);
}
TensorNet dirichlet_extremal(const TensorNet& data, FixedSet fixed) { return cmc_detail::dirichlet_impl(data, fixed); }

}  // namespace bpde
