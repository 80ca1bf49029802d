// The least-squares mean-curvature functional of the cmc problem (cmc.h, "The least-squares
// mean-curvature functional"; docs/cmc_algorithm.md, "The least squares of the mean curvature"): from the D_H
// critical point, Levenberg–Marquardt on Φ = ∫ ρ (H_x − H)² dA (mean_curvature_least_squares.h):
// the library's own loop (solver newton, minimise_newton below, over levenberg_marquardt.h) or ceres::Solve with one residual
// block per node (solver ceres, mean_curvature_ceres.cpp).
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "bezierpde/core/progress.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/complex_net.h"
#include "bezierpde/solvers/optim/levenberg_marquardt.h"
#include "bezierpde/energies/mean_curvature_least_squares.h"
#include "bezierpde/solvers/cmc/mean_curvature_minimise.h"
#include "bezierpde/solvers/summary.h"

namespace bpde::cmc_detail {
using namespace bpde::optim;  // the generic least squares and trust-region steps (solvers/optim)
namespace {

// The rule minimised: the corner-collapsed rules with q = ⌈n/2⌉ + 4 points per direction
// (n the larger degree of a tensor net); the check rule has q + ⌈q/2⌉.
int rule_q(int n, int extra) {
  const int q = (n + 1) / 2 + 4;
  return q + extra * ((q + 1) / 2);
}
MeanCurvatureLeastSquares form_for(const TriangularNet& net, int extra) {
  return MeanCurvatureLeastSquares::triangular(net.n(), rule_q(net.n(), extra));
}
MeanCurvatureLeastSquares form_for(const TensorNet& net, int extra) {
  return MeanCurvatureLeastSquares::tensor(net.n(), net.m(), rule_q(std::max(net.n(), net.m()), extra));
}
// A complex: the patch's rule (all patches have one kind and degree), summed over the patches.
MeanCurvatureLeastSquares form_for(const ComplexNet& net, int extra) {
  const int q = rule_q(net.n(), extra);
  auto patch = std::make_shared<const MeanCurvatureLeastSquares>(
      net.triangular() ? MeanCurvatureLeastSquares::triangular(net.n(), q)
                       : MeanCurvatureLeastSquares::tensor(net.n(), net.n(), q));
  return MeanCurvatureLeastSquares::assembled(std::move(patch), net.assembly());
}

}  // namespace

namespace {

// What the V form says when its start cannot be put on V = V0 (LsStop::ConstraintUnmet).
constexpr const char* kVolumeUnmet =
    "the start could not be put on the volume constraint V = v0 (Newton steps along ∇V from the minimiser of D "
    "at v0 did not converge)";

// The unknowns of the loop (levenberg_marquardt.h): the free coordinates of P, point-major
// (3a + c for free[a], coordinate c), and in the V form H last.
Eigen::VectorXd unknowns(const Eigen::MatrixX3d& P, const std::vector<int>& free, const double* H) {
  const Eigen::Index np = 3 * Eigen::Index(free.size());
  Eigen::VectorXd x(np + (H ? 1 : 0));
  for (size_t a = 0; a < free.size(); ++a) x.segment<3>(3 * Eigen::Index(a)) = P.row(free[a]).transpose();
  if (H) x(np) = *H;
  return x;
}
// P with its free rows from x (the inverse of unknowns for P).
void set_free(Eigen::MatrixX3d& P, const std::vector<int>& free, const Eigen::VectorXd& x) {
  for (size_t a = 0; a < free.size(); ++a) P.row(free[a]) = x.segment<3>(3 * Eigen::Index(a)).transpose();
}

// Levenberg–Marquardt with geodesic acceleration (levenberg_marquardt.h) on Φ = ‖r‖² over the free
// rows of P (in place) and, with vt, over H too subject to V(P) = V0 (each trial point put back on
// V = V0 by restore_volume, so every iterate is feasible). Progress stage "cmc least squares".
// With check (the finer rule), every kRuleCheckEvery accepted steps √Φ is also taken by it; when it
// reads more than kRuleAgreement × √Φ of the rule minimised (and above the target), the loop stops
// (LsStop::Interrupted) and P, H go back to the last point where the two agreed.
LsOutcome lm_loop(const MeanCurvatureLeastSquares& f, const MeanCurvatureLeastSquares* check, Eigen::MatrixX3d& P,
                  const std::vector<int>& free, double& H, const VolumeTarget* vt, double target, int max_iterations,
                  bool geodesic, const ProgressFn& progress) {
  const Eigen::Index np = 3 * Eigen::Index(free.size());
  const double H_fixed = H;
  // Scratch net of the callbacks: only its free rows change.
  Eigen::MatrixX3d Q = P;
  Eigen::VectorXd agreed = unknowns(P, free, vt ? &H : nullptr);
  LeastSquaresProblem problem;
  if (check)
    problem.monitor = [&, Qm = P](const Eigen::VectorXd& x, int iterations, double phi) mutable {
      if (iterations == 0) {  // the start, restored onto V = V0 in the V form: agreed by definition
        agreed = x;
        return true;
      }
      if (iterations % kRuleCheckEvery != 0) return true;
      set_free(Qm, free, x);
      if (!rules_agree(*check, Qm, vt ? x(np) : H_fixed, phi, target)) return false;
      agreed = x;
      return true;
    };
  problem.residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    set_free(Q, free, x);
    const double h = vt ? x(np) : H_fixed;
    if (!J) {
      f.residuals(Q, h, &r);
      return;
    }
    Eigen::MatrixXd Jp;
    Eigen::VectorXd dH;
    f.residuals(Q, h, &r, &free, &Jp, vt ? &dH : nullptr);
    if (!vt) {
      *J = std::move(Jp);
      return;
    }
    J->resize(Jp.rows(), Jp.cols() + 1);
    J->leftCols(Jp.cols()) = Jp;
    J->col(Jp.cols()) = dH;  // ∂r_q/∂H = −√(w_q ρ_q |N_q|)
  };
  if (vt) {
    problem.constraint = [&](const Eigen::VectorXd& x, Eigen::VectorXd* grad) {
      set_free(Q, free, x);
      if (grad) {
        const Eigen::MatrixX3d G = vt->form.gradient_rows(Q, free);
        *grad = Eigen::VectorXd::Zero(x.size());  // 0 for H
        for (size_t a = 0; a < free.size(); ++a) grad->segment<3>(3 * Eigen::Index(a)) = G.row(Eigen::Index(a)).transpose();
      }
      return vt->form.value(Q) - vt->V0;
    };
    problem.restore = [&](Eigen::VectorXd& x) {
      set_free(Q, free, x);
      const bool ok = restore_volume(*vt, Q, free);
      x.head(np) = unknowns(Q, free, nullptr);
      return ok;
    };
  }
  LevenbergMarquardtOptions lo;
  lo.target = target;
  lo.max_iterations = max_iterations;
  lo.geodesic_acceleration = geodesic;
  lo.stage = "cmc least squares";
  Eigen::VectorXd x = unknowns(P, free, vt ? &H : nullptr);
  const LsOutcome out = levenberg_marquardt(problem, x, lo, progress);
  if (out.stop == LsStop::Interrupted) x = agreed;
  set_free(P, free, x);
  if (vt) H = x(np);
  return out;
}

}  // namespace

// Back onto V = V0 along the volume gradient over the free points: at most 8 Newton steps on the
// one equation V(P) = V0 (V is cubic in P; two steps from a Levenberg–Marquardt trial suffice in
// practice). False when it does not get there.
bool restore_volume(const VolumeTarget& vt, Eigen::MatrixX3d& P, const std::vector<int>& free) {
  for (int it = 0; it < 8; ++it) {
    const double c = vt.form.value(P) - vt.V0;
    if (!std::isfinite(c)) return false;
    if (std::abs(c) <= 1e-14 * vt.scale) return true;
    const Eigen::MatrixX3d G = vt.form.gradient_rows(P, free);
    const double g2 = G.squaredNorm();
    if (!(g2 > 0)) return false;
    for (size_t a = 0; a < free.size(); ++a) P.row(free[a]) -= (c / g2) * G.row(Eigen::Index(a));
  }
  return std::abs(vt.form.value(P) - vt.V0) <= 1e-14 * vt.scale;
}

// Levenberg–Marquardt on Φ(P) = ‖r‖² over the free rows of P (in place), until √Φ <= target, a
// stall, no step, or max_iterations. A trial step is taken only when it and the new Φ are finite.
// Progress (stage "cmc least squares"): the fraction of the way from the start's √Φ to the target
// on a log scale, reported after every iteration, and 1 at the end.
LsOutcome minimise_newton(const MeanCurvatureLeastSquares& f, const MeanCurvatureLeastSquares* check,
                          Eigen::MatrixX3d& P, const std::vector<int>& free, double H, double target,
                          int max_iterations, bool geodesic, const ProgressFn& progress) {
  return lm_loop(f, check, P, free, H, nullptr, target, max_iterations, geodesic, progress);
}

namespace {

// One minimisation of Φ from P (and H) by the minimiser o.solver picks, to √Φ <= 0.7 × tolerance (so
// that the check rule, finer, does not miss it by its own small error), with the rule check. When
// the check rule stops agreeing with the rule minimised during the minimisation (the iterate is
// exploiting the gaps between the nodes, folding the parametrisation where Φ cannot see it), the
// minimisation goes on from the last agreed point with the next finer pair of rules; when the rule
// minimised reaches the target but the check rule reads above the tolerance (they disagree by less
// than the 2× of the fold test, e.g. 1.0e-6 … 1.4e-6 against 7e-7 on the circle at n = 12, 14:
// docs/cmc_algorithm.md, "The routes"), it goes on from the point reached with the next finer pair. At most
// kMaxRuleRefinements times and max_iterations iterations in all.
struct LsRun {
  LsOutcome ls;
  bool folded = false;  ///< the rules stopped agreeing at the end (ls.stop Interrupted, or MaxIterations after it)
  int extra = 0, folds = 0, misses = 0;
  std::optional<MeanCurvatureLeastSquares> f, check;
};

template <class Net>
LsRun minimise_checked(const Net& data, const CmcOptions& o, Eigen::MatrixX3d& P, const std::vector<int>& free,
                       double& H, const VolumeTarget* v, double tolerance, int max_iterations) {
  LsRun run;
  const double target = 0.7 * tolerance;
  int iterations = 0;
  // Progress: the minimisations of the refinements are one stage "cmc least squares". Each reports
  // the log-scale way from its own start's √Φ to the target; with a the fraction where the one
  // before ended, a + (1 − a) f is the way from the first start (exact when each starts where the
  // one before ended; the last agreed point can lie before it, so it is kept from falling), and the
  // stage is finished once, at the end.
  double base = 0.0, reached = 0.0;
  ProgressFn progress;
  if (o.progress)
    progress = [&](std::string_view stage, double done, double total) {
      if (!(total > 0) || done >= total) return;  // one minimisation's end
      reached = std::max(reached, base + (1.0 - base) * (done / total));
      o.progress(stage, reached, 1.0);
    };
  while (true) {
    base = reached;
    run.f.emplace(form_for(data, run.extra));
    run.check.emplace(form_for(data, run.extra + 1));
    const int left = max_iterations - iterations;
    // The Ceres route's blocks are the nodes of one patch: an assembled form (a complex) is
    // minimised by the library's loop whatever the solver (complex_net.h).
    if (o.solver == CmcSolver::Ceres && !run.f->is_assembled())
      run.ls = minimise_ceres(*run.f, &*run.check, P, free, H, v, target, left, progress);
    else if (v)
      run.ls = lm_loop(*run.f, &*run.check, P, free, H, v, target, left, o.geodesic_acceleration, progress);
    else
      run.ls = minimise_newton(*run.f, &*run.check, P, free, H, target, left, o.geodesic_acceleration, progress);
    iterations += run.ls.iterations;
    const bool check_misses = run.ls.stop == LsStop::Reached && !(std::sqrt(run.check->value(P, H)) <= tolerance);
    if (!(run.ls.stop == LsStop::Interrupted || check_misses) || run.extra >= kMaxRuleRefinements ||
        iterations >= max_iterations)
      break;
    ++(check_misses ? run.misses : run.folds);
    ++run.extra;
  }
  report(o.progress, "cmc least squares", 1.0, 1.0);
  run.ls.iterations = iterations;
  run.folded = run.ls.stop == LsStop::Interrupted;
  if (run.folded && iterations >= max_iterations) run.ls.stop = LsStop::MaxIterations;
  return run;
}

// Φ is quadratic in H (r = r₀ + H ∂r/∂H): the V form reports the best H for the surface reached,
// H* = −⟨∂r/∂H, r₀⟩/‖∂r/∂H‖², the ρ-weighted mean of its H_x (never raises Φ, leaves V as it is).
// The loops stop at √Φ <= target, not at ∂Φ/∂H = 0; on the circle their last H was up to 9.6e-8 off
// the cap's, H* is within 4.2e-8 (docs/cmc_algorithm.md, "The routes").
double best_h(const MeanCurvatureLeastSquares& f, const Eigen::MatrixX3d& P, double H) {
  Eigen::VectorXd r0, dH;
  f.residuals(P, 0.0, &r0, nullptr, nullptr, &dH);
  const double hh = dH.squaredNorm(), Hs = hh > 0 ? -dH.dot(r0) / hh : H;
  return std::isfinite(Hs) && f.value(P, Hs) <= f.value(P, H) ? Hs : H;
}

// One route's end: the net, its H, the minimisation that reached it, where it started, and the
// Levenberg–Marquardt iterations of the whole route.
struct LsEnd {
  Eigen::MatrixX3d P;
  double H = 0.0;
  LsRun run;
  std::string start_note;
  int iterations = 0;
};

// What a route's end is: 0 converged, 1 regular and on V = V0 but above the tolerance, 2 otherwise
// (a degenerate parametrisation, or V off V0); with Φ and √Φ by the check rule.
struct LsGrade {
  int rank = 2;
  double phi = 0.0, residual = 0.0;
  Regularity reg;
  double v_off = 0.0;
};

template <class Net>
LsGrade grade(const Net& data, const CmcOptions& o, const LsEnd& e, const VolumeTarget* vt) {
  LsGrade g;
  const Net net = make_net(data, e.P);
  g.reg = regularity(net, area(net));
  g.v_off = vt ? std::abs(vt->form.value(e.P) - vt->V0) / vt->scale : 0.0;
  g.phi = e.run.check->value(e.P, e.H);
  g.residual = std::sqrt(g.phi);
  if (g.reg.ok && g.v_off <= o.tolerance) g.rank = g.residual <= o.mean_curvature_tolerance ? 0 : 1;
  return g;
}

// The V form's second route (docs/cmc_algorithm.md, "The routes", "Past the hemisphere"): Φ minimised at
// V1 = Vref + (V0 − Vref)/k for k = 4, 16, 64, 256 in turn (Vref the volume of the Dirichlet
// extremal, so V1 lies between the nearly minimal surface and V0 wherever the origin is) from the
// minimiser of D there, then V stepped from V1 to V0 by the step control of the H continuation over
// V − V1 (first step (V0 − V1)/8; a step doubles the next after at most kEasyLsStep iterations,
// halves on a failure, down to min_step × max(1, |V − V1|)). The predictor is the secant through
// the last two points accepted (P and H; from V1 the point itself), put back on the new V by the
// loop's own restoration. A point (the start at V1 too) is accepted when its minimisation ends with
// the rules agreeing, at a regular parametrisation on its V, with √Φ <= max(kLsStepResidual, the
// tolerance) by the check rule: the minimiser of Φ is continued whether it meets the tolerance or
// not (where the degree is too low for the tolerance it stalls above it: 4.3e-6 at the small cap of
// H = −0.9 on the circle at n = 8). A V1 whose start or continuation fails gives way to the next.
// Limits over the whole route (all V1): max_least_squares_iterations Levenberg–Marquardt iterations
// (a step before V0 at most kLsStepIterations of them, the step at V0 what is left) and
// max_continuation_steps step attempts. Returns the end at V0 (its `iterations` the route's), or
// nothing with `why` saying where each V1 stopped; `iterations` gets the route's solver iterations
// (the D starts' too).
constexpr int kEasyLsStep = 20;
constexpr int kLsStepIterations = 200;
constexpr double kLsStepResidual = 1e-2;

// The steps of one continuation of the least squares in V from `cur` (at V1) to V0: the secant
// predictor through the last two ends, minimise_at(end, V) as the corrector, the step control of
// the H continuation over V − V1 (at most `attempts` attempts, counted down; `budget` the least
// squares' iterations left, which minimise_at counts down). The steps taken, with cur at V0; or
// nothing, with `why` saying where it stopped.
template <class Minimise>
std::optional<int> continue_from(LsEnd& cur, double V1, double V0, const CmcOptions& o, int& attempts,
                                 const int& budget, const Minimise& minimise_at, std::string& why) {
  const double span = V0 - V1;
  CmcOptions oc = o;
  oc.max_continuation_steps = attempts;
  StepController control(span, span / 8, oc);
  LsEnd prev = cur;
  double v_prev = V1, v_cur = V1;
  int taken = 0;
  while (!control.reached_target()) {
    if (budget <= 0 || !control.attempt()) {
      why = "stopped at V = " + num(v_cur) + " (" +
            (budget <= 0 ? "max_least_squares_iterations" : "max_continuation_steps") + ")";
      return std::nullopt;
    }
    --attempts;
    const StepController::Step step = control.propose();
    const double vn = step.hn == span ? V0 : V1 + step.hn;
    LsEnd next = cur;
    if (v_cur != v_prev) {
      const double t = (vn - v_cur) / (v_cur - v_prev);
      next.P += t * (cur.P - prev.P);
      next.H += t * (cur.H - prev.H);
    }
    if (minimise_at(next, vn)) {
      prev = std::move(cur);
      cur = std::move(next);
      v_prev = v_cur;
      v_cur = vn;
      ++taken;
      control.accept(step, cur.run.ls.iterations, kEasyLsStep);
    } else if (!control.reject(step)) {
      why = "the step fell below min_step at V = " + num(v_cur);
      return std::nullopt;
    }
  }
  return taken;
}

template <class Net>
std::optional<LsEnd> continue_in_volume(const Net& data, const CmcOptions& o, const VolumeTarget& vt, double Vref,
                                        const std::vector<int>& free, int& iterations, int& steps, std::string& why) {
  const double V0 = vt.V0;
  std::string tried;
  auto fail = [&](double V1, const std::string& what) { tried += (tried.empty() ? "" : "; ") + num(V1) + ": " + what; };
  int budget = o.max_least_squares_iterations, attempts = o.max_continuation_steps, ls_iterations = 0;
  for (const double k : {4.0, 16.0, 64.0, 256.0}) {
    const double V1 = Vref + (V0 - Vref) / k;
    if (!(V1 != V0)) break;
    if (budget <= 0 || attempts <= 0) {
      fail(V1, budget <= 0 ? "max_least_squares_iterations used up" : "max_continuation_steps used up");
      break;
    }
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    od.solver = CmcSolver::NLopt;
    od.V = V1;
    const CmcResult<Net> start = solve_cmc(data, od);
    iterations += start.summary.iterations;
    if (!start.summary.converged) {
      fail(V1, "the minimiser of D there did not converge");
      continue;
    }
    LsEnd cur{start.net.points(), start.H, {}, {}, 0};
    auto minimise_at = [&](LsEnd& e, double V) {
      const VolumeTarget v{vt.form, V, vt.scale};
      e.run = minimise_checked(data, o, e.P, free, e.H, &v, o.mean_curvature_tolerance,
                               V == V0 ? budget : std::min(budget, kLsStepIterations));
      budget -= e.run.ls.iterations;
      ls_iterations += e.run.ls.iterations;
      iterations += e.run.ls.iterations;
      const LsStop stop = e.run.ls.stop;
      if (e.run.folded || stop == LsStop::NonFinite || stop == LsStop::ConstraintUnmet) return false;
      const LsGrade g = grade(data, o, e, &v);
      return g.rank <= 1 && g.residual <= std::max(kLsStepResidual, o.mean_curvature_tolerance);
    };
    if (!minimise_at(cur, V1)) {
      fail(V1, "no regular start there with √Φ <= " + num(kLsStepResidual));
      continue;
    }
    std::string stopped;
    const std::optional<int> taken = continue_from(cur, V1, V0, o, attempts, budget, minimise_at, stopped);
    if (!taken) {
      fail(V1, stopped);
      continue;
    }
    steps += *taken;
    cur.start_note = "continued in V from V1 = " + num(V1) + " (from the minimiser of D there, H = " +
                     num(start.H, 3) + ") in " + std::to_string(*taken) + " step(s)";
    cur.iterations = ls_iterations;
    return cur;
  }
  why = "no continuation in V from V1 towards v0 (V1 = " + (tried.empty() ? std::string("none") : tried) + ")";
  return std::nullopt;
}

// The V form's start did not converge (past the hemisphere it folds: docs/cmc_measurements.md):
// the continuation in V from V1 towards v0, kept when it ends better (converged, or regular and
// on V0 where the first end is not, or a lower √Φ, both read by the finer of the two check rules).
// end, g, the result's iterations and steps move to the continuation's where it is kept; the
// returned note says how the other ended.
template <class Net>
std::string try_continuation_in_volume(const Net& data, const CmcOptions& o, const CmcFunctional& cf,
                                       const VolumeTarget& vt, const std::vector<int>& free, LsEnd& end, LsGrade& g,
                                       CmcResult<Net>& res) {
  const VolumeTarget* v = &vt;
  const DirichletStart ds = dirichlet_start(data, o);
  const double Vref = cf.volume(ds.p.P);
  int iterations = 0, steps = 0;
  std::string why;
  std::optional<LsEnd> cont = continue_in_volume(data, o, vt, Vref, free, iterations, steps, why);
  res.summary.iterations += iterations;
  if (cont) cont->H = best_h(*cont->run.f, cont->P, cont->H);
  const LsGrade g2 = cont ? grade(data, o, *cont, v) : LsGrade{};
  bool better = cont && g2.rank < g.rank;
  double r1 = g.residual, r2 = g2.residual;
  if (cont && g2.rank == 1 && g.rank == 1) {
    const int extra = std::max(end.run.extra, cont->run.extra) + 1;
    const MeanCurvatureLeastSquares fine = form_for(data, extra);
    r1 = std::sqrt(fine.value(end.P, end.H));
    r2 = std::sqrt(fine.value(cont->P, cont->H));
    better = r2 < r1;
  }
  const std::string first = g.rank == 1 ? "above the tolerance (√Φ = " + num(r1, 3) + ")"
                            : !g.reg.ok  ? std::string("at a degenerate parametrisation")
                                         : std::string("off V0");
  if (!better)
    return cont ? "; the continuation in V from V1 towards v0 ended no better (√Φ = " + num(r2, 3) + ")" : "; " + why;
  end = std::move(*cont);
  g = g2;
  res.continuation_steps += steps;
  return "; from the minimiser of D at V0 it ended " + first;
}

// Why the least squares stopped above the tolerance, for the message.
std::string stop_reason(const LsRun& run, const CmcOptions& o) {
  std::string why;
  switch (run.ls.stop) {
    case LsStop::Reached:
      why = " by the check rule (q = " + std::to_string(run.check->points_per_direction()) +
            "), although the rule minimised (q = " + std::to_string(run.f->points_per_direction()) +
            ") reached " + num(0.7 * o.mean_curvature_tolerance, 3) + ": the rule does not resolve Φ at this net";
      break;
    case LsStop::Stalled:
      why = " and no longer falls (the degree is too low for it)";
      break;
    case LsStop::NoStep:
      why = " and no Levenberg–Marquardt step lowers it (the degree is too low for it)";
      break;
    case LsStop::MaxIterations:
      why = " after max_least_squares_iterations = " + std::to_string(o.max_least_squares_iterations) +
            " (a library option)";
      break;
    case LsStop::NonFinite:
      why = ": Φ or its Jacobian is not finite at the net reached";
      break;
    case LsStop::ConstraintUnmet:
      why = std::string(": ") + kVolumeUnmet;
      break;
    case LsStop::Interrupted:
      why = ": the rules refined " + std::to_string(kMaxRuleRefinements) + " times (now q = " +
            std::to_string(run.f->points_per_direction()) + " and " +
            std::to_string(run.check->points_per_direction()) +
            " points per direction) still stop agreeing, so the parametrisation is folding where Φ's rule does not "
            "see it; the net is the last point where they agreed";
      break;
  }
  return why;
}

// The result at the least squares' end and its verdict: degenerate parametrisation, V off V0,
// √Φ above the tolerance (with why the least squares stopped), or converged.
template <class Net>
void fill_result(const Net& data, const CmcOptions& o, const CmcFunctional& cf, const LsEnd& end, const LsGrade& g,
                 CmcResult<Net>& res) {
  const LsRun& run = end.run;
  const double H = end.H;
  const Eigen::MatrixX3d& P = end.P;
  const Net net = make_net(data, P);
  res.net = net;
  res.H = H == 0.0 ? 0.0 : H;  // no "-0" in the report
  res.D = cf.dirichlet(P);
  res.V = cf.volume(P);
  res.DH = res.D + 2.0 * H * res.V;
  res.A = area(net);
  res.energy = g.phi;
  res.quadrature_points = run.f->points_per_direction();
  res.quadrature_grading = 1;  // the plain corner-collapsed rules (mean_curvature_least_squares.h)
  res.quadrature_nodes = run.f->nodes();
  res.summary.residual = g.residual;
  const std::string refined =
      run.extra > 0 ? " (rule refined to q = " + std::to_string(run.f->points_per_direction()) + ": " +
                          (run.folds > 0 ? "the check rule stopped agreeing with the coarser one" : "") +
                          (run.folds > 0 && run.misses > 0 ? "; " : "") +
                          (run.misses > 0 ? "the check rule read above the tolerance where the coarser one met it"
                                          : "") +
                          ")"
                    : std::string();
  const bool ceres = o.solver == CmcSolver::Ceres && !run.f->is_assembled();
  const std::string what = "least squares of the mean curvature " + end.start_note + refined + ": √Φ = " +
                           num(res.summary.residual, 3) + (o.V ? " at H = " + num(H, 6) : std::string()) +
                           " after " + std::to_string(end.iterations) +
                           (ceres ? " Ceres Levenberg–Marquardt iteration(s)" : " Levenberg–Marquardt iteration(s)");
  const Regularity reg = g.reg.ok ? final_regularity(net, res.A) : g.reg;
  res.parametrisation = parametrisation_check(reg);
  if (!reg.ok) {
    res.summary.set_failed(Status::NoConvergence,
                           "degenerate parametrisation: " + reg.describe() + " (not a CMC surface); " + what);
  } else if (!(g.v_off <= o.tolerance)) {
    res.summary.set_failed(Status::NoConvergence,
                           what + ", but V misses V0 by " + num(g.v_off, 3) + " (relative): " +
                               (run.ls.stop == LsStop::ConstraintUnmet ? kVolumeUnmet : "above the tolerance"));
  } else if (!(res.summary.residual <= o.mean_curvature_tolerance)) {
    const std::string why = stop_reason(run, o);
    res.summary.set_failed(Status::NoConvergence,
                           what + " is above the tolerance " + num(o.mean_curvature_tolerance, 3) + why);
  } else {
    res.summary.message = what;
    res.summary.set_converged();
  }
}

template <class Net>
CmcResult<Net> solve_mean_curvature_impl(const Net& data, const CmcOptions& o,
                                         const CmcResult<Net>* dirichlet = nullptr) {
  CmcResult<Net> res;
  res.functional = CmcFunctionalKind::MeanCurvature;
  {
    ScopedTimer timer(res.summary.seconds);
    o.validate();
    // The start: the paper's D_H critical point at H (or the last point of its branch), by the
    // newton continuation whatever o.solver (which picks the least-squares minimiser); in the V
    // form the minimiser of D at V = V0 (nlopt) and its multiplier H; a D start already solved
    // (`dirichlet`) is taken as it is.
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    od.solver = o.V ? CmcSolver::NLopt : CmcSolver::Newton;
    const CmcResult<Net> start = dirichlet ? *dirichlet : solve_cmc(data, od);
    res.continuation_steps = start.continuation_steps;
    res.summary.iterations = start.summary.iterations;
    const std::vector<int> free = data.free_indices(o.fixed);
    const auto cf = functional_for(data);
    std::optional<VolumeTarget> vt;
    if (o.V) {
      // The volume's scale: the size of its terms, |V0|, or the start's area^(3/2), whichever is
      // largest (a planar start through the origin has value_scale 0; so has V0 = 0).
      const double vscale = std::max(
          {cf->volume_form().value_scale(start.net.points()), std::abs(*o.V), std::pow(area(start.net), 1.5)});
      vt.emplace(VolumeTarget{cf->volume_form(), *o.V, vscale > 0 ? vscale : 1.0});
    }
    const VolumeTarget* v = vt ? &*vt : nullptr;
    LsEnd end{start.net.points(), o.V ? start.H : o.H, {}, {}, 0};
    end.run = minimise_checked(data, o, end.P, free, end.H, v, o.mean_curvature_tolerance,
                               o.max_least_squares_iterations);
    end.iterations = end.run.ls.iterations;
    res.summary.iterations += end.run.ls.iterations;
    end.start_note = o.V ? "from the minimiser of D at V = " + num(*o.V, 3) + " (H = " + num(start.H, 3) + ")"
                     : start.summary.converged ? "from the D_H critical point at H = " + num(o.H, 3)
                                               : "from the last D_H branch point (H = " + num(start.H, 3) + ")";
    if (vt && end.run.ls.stop != LsStop::ConstraintUnmet) end.H = best_h(*end.run.f, end.P, end.H);
    LsGrade g = grade(data, o, end, v);
    std::string route_note;
    if (vt && g.rank > 0) route_note = try_continuation_in_volume(data, o, *cf, *vt, free, end, g, res);
    fill_result(data, o, *cf, end, g, res);
    res.summary.message += route_note;
  }
  return res;
}

}  // namespace

CmcResult<TriangularNet> solve_mean_curvature(const TriangularNet& data, const CmcOptions& options) {
  return solve_mean_curvature_impl(data, options);
}
CmcResult<TensorNet> solve_mean_curvature(const TensorNet& data, const CmcOptions& options) {
  return solve_mean_curvature_impl(data, options);
}
CmcResult<TriangularNet> solve_mean_curvature(const TriangularNet& data, const CmcOptions& options,
                                              const CmcResult<TriangularNet>* dirichlet) {
  return solve_mean_curvature_impl(data, options, dirichlet);
}
CmcResult<TensorNet> solve_mean_curvature(const TensorNet& data, const CmcOptions& options,
                                          const CmcResult<TensorNet>* dirichlet) {
  return solve_mean_curvature_impl(data, options, dirichlet);
}
// A complex: at most kMaxMeanCurvatureCoordinates free coordinates (the loop is dense), and asked
// for directly, solver newton (the Ceres route has no assembled form); from the area solve's
// mean-curvature-start (with its D start) any solver, minimised by the newton loop.
CmcResult<ComplexNet> solve_mean_curvature(const ComplexNet& data, const CmcOptions& options,
                                           const CmcResult<ComplexNet>* dirichlet) {
  if (!mean_curvature_fits(data))
    throw UnsupportedProblem("cmc on a complex: the mean-curvature functional takes at most " +
                             std::to_string(kMaxMeanCurvatureCoordinates) + " free coordinates (this complex has " +
                             std::to_string(3 * data.free_indices(options.fixed).size()) + ")");
  return solve_mean_curvature_impl(data, options, dirichlet);
}
CmcResult<ComplexNet> solve_mean_curvature(const ComplexNet& data, const CmcOptions& options) {
  if (options.solver == CmcSolver::Ceres)
    throw UnsupportedProblem("cmc on a complex: the mean-curvature functional takes the solver newton");
  return solve_mean_curvature(data, options, nullptr);
}

}  // namespace bpde::cmc_detail
