// The least-squares mean-curvature functional of the cmc problem (cmc.h, "The least-squares
// mean-curvature functional"; docs/cmc.md, "Least squares of the mean curvature"): from the D_H
// critical point, Levenberg–Marquardt on Φ = ∫ ρ (H_x − H)² dA (mean_curvature_least_squares.h):
// the library's own loop (solver newton, minimise_newton below) or ceres::Solve with one residual
// block per node (solver ceres, mean_curvature_ceres.cpp).
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "bezierpde/core/progress.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/solvers/cmc/area_functional.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/cmc_area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/mean_curvature_least_squares.h"
#include "bezierpde/solvers/cmc/mean_curvature_minimise.h"
#include "bezierpde/solvers/summary.h"

namespace bpde::cmc_detail {
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

}  // namespace

namespace {

// What the V form says when its start cannot be put on V = V0 (LsStop::VolumeUnmet).
constexpr const char* kVolumeUnmet =
    "the start could not be put on the volume constraint V = v0 (Newton steps along ∇V from the minimiser of D "
    "at v0 did not converge)";

// The volume constraint of the V form: V(P) = V0 with H an unknown (nullptr in the H form).
struct VolumeTarget {
  const VolumeForm& form;
  double V0;
  double scale;  ///< > 0, the volume's scale at the start: |V − V0| <= 1e-14 × scale is "on the constraint"
};

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

// The residuals r and their Jacobian over the unknowns: the free coordinates (column 3a + c) and,
// in the V form, H (the last column, ∂r_q/∂H = −√(w_q|N_q|)).
void evaluate(const MeanCurvatureLeastSquares& f, const Eigen::MatrixX3d& P, const std::vector<int>& free, double H,
              bool with_H, Eigen::VectorXd& r, Eigen::MatrixXd& J) {
  Eigen::MatrixXd Jp;
  Eigen::VectorXd dH;
  f.residuals(P, H, &r, &free, &Jp, with_H ? &dH : nullptr);
  if (!with_H) {
    J = std::move(Jp);
    return;
  }
  J.resize(Jp.rows(), Jp.cols() + 1);
  J.leftCols(Jp.cols()) = Jp;
  J.col(Jp.cols()) = dH;
}

// P with the step s (3 per free point, in the order of free) added to its free rows.
Eigen::MatrixX3d moved(const Eigen::MatrixX3d& P, const std::vector<int>& free, const Eigen::VectorXd& s) {
  Eigen::MatrixX3d Pn = P;
  for (size_t i = 0; i < free.size(); ++i) Pn.row(free[i]) += s.segment<3>(3 * Eigen::Index(i)).transpose();
  return Pn;
}

// Geodesic acceleration (Transtrum and Sethna 2012, cmc.h): the finite-difference step h of the
// second directional derivative along δ (δ is scaled to the problem, so h is relative; GSL's
// default is 0.02) and the largest 2‖a‖/‖δ‖ taken, α = 0.75. The paper and GSL take ‖a‖/‖δ‖ ≤ α;
// the bound here is twice as strict because that was measured better on the circle (docs/cmc.md,
// "Geodesic acceleration": the paper's bound takes the same iterations or up to 1.4× fewer at
// n = 8 … 14, except at n = 10, H = −0.9: 15 % more at √Φ ≤ 7e-7, and at √Φ ≤ 7e-9 it runs out of
// 2000 iterations where this one takes 407).
constexpr double kGeodesicH = 0.1;
constexpr double kGeodesicAlpha = 0.75;

// Levenberg–Marquardt on Φ = ‖r‖² over the free rows of P (in place) and, with vt, over H too
// subject to V(P) = V0: the step solves the equality-constrained LM subproblem
//     min ‖r + J d‖² + λ dᵀ diag(JᵀJ) d   subject to  ∇Vᵀ d_P = V0 − V(P)
// by its KKT system (two solves with the one Cholesky factor), and a trial point is put back on
// V = V0 (restore_volume) before Φ is compared, so every iterate is feasible. With geodesic, the
// step is δ + a/2 (geodesic acceleration, cmc.h); the gain ratio's prediction stays δ's.
LsOutcome lm_loop(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free, double& H,
                  const VolumeTarget* vt, double target, int max_iterations, bool geodesic,
                  const ProgressFn& progress) {
  LsOutcome out;
  report(progress, "cmc least squares", 0, 1);
  if (vt) {  // on a copy: a start that cannot be restored is reported as it was given
    Eigen::MatrixX3d Pr = P;
    if (!restore_volume(*vt, Pr, free)) {
      out.stop = LsStop::VolumeUnmet;
      report(progress, "cmc least squares", 1, 1);
      return out;
    }
    P = std::move(Pr);
  }
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  evaluate(f, P, free, H, vt, r, J);
  double phi = r.squaredNorm(), lambda = 1e-3;
  std::vector<double> history{phi};
  const double start = std::sqrt(phi);
  const Eigen::Index n = J.cols(), np = 3 * Eigen::Index(free.size());
  while (true) {
    if (!std::isfinite(phi) || !J.allFinite()) {
      out.stop = LsStop::NonFinite;
      break;
    }
    if (std::sqrt(phi) <= target) {
      out.stop = LsStop::Reached;
      break;
    }
    if (out.iterations >= max_iterations) {
      out.stop = LsStop::MaxIterations;
      break;
    }
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    A.selfadjointView<Eigen::Lower>().rankUpdate(J.transpose());
    A = A.selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd g = J.transpose() * r;
    const Eigen::VectorXd diag = A.diagonal().cwiseMax(1e-12 * A.diagonal().maxCoeff());
    Eigen::VectorXd aV;  // the constraint's gradient over the unknowns (0 for H)
    double c = 0.0;
    if (vt) {
      aV = Eigen::VectorXd::Zero(n);
      const Eigen::MatrixX3d G = vt->form.gradient_rows(P, free);
      for (size_t i = 0; i < free.size(); ++i) aV.segment<3>(3 * Eigen::Index(i)) = G.row(Eigen::Index(i)).transpose();
      c = vt->form.value(P) - vt->V0;
    }
    bool accepted = false;
    for (int tries = 0; tries < 30 && !accepted; ++tries) {
      Eigen::MatrixXd M = A;
      M.diagonal() += lambda * diag;
      const Eigen::LLT<Eigen::MatrixXd> llt(M);
      Eigen::VectorXd d, e;
      if (llt.info() == Eigen::Success) {
        d = -llt.solve(g);
        if (vt) {  // d = d0 − μ e with e = M⁻¹a and aᵀd = −c (a = aV, the constraint's gradient)
          e = llt.solve(aV);
          const double ae = aV.dot(e);
          d = ae > 0 ? Eigen::VectorXd(d - ((aV.dot(d) + c) / ae) * e) : Eigen::VectorXd();
        }
      }
      if (d.size() != g.size() || !d.allFinite()) {
        lambda *= 10;
        continue;
      }
      Eigen::VectorXd step = d;
      const double dd = d.dot(diag.asDiagonal() * d);
      if (geodesic && dd > 0) {
        // Transtrum–Sethna geodesic acceleration (cmc.h): r_δδ by the finite difference along δ,
        // a from the same factor (in the V form also tangent to the constraint, aᵀ∇V = 0: first
        // order only; restore_volume puts the trial point back on V = V0).
        Eigen::VectorXd rh;
        f.residuals(moved(P, free, kGeodesicH * d), vt ? H + kGeodesicH * d(np) : H, &rh);
        const Eigen::VectorXd rvv = (2.0 / kGeodesicH) * ((rh - r) / kGeodesicH - J * d);
        Eigen::VectorXd a = -llt.solve(J.transpose() * rvv);
        if (vt) a -= (aV.dot(a) / aV.dot(e)) * e;
        const double ratio2 = a.dot(diag.asDiagonal() * a) / dd;
        if (!a.allFinite() || !(4.0 * ratio2 <= kGeodesicAlpha * kGeodesicAlpha)) {
          lambda *= 10;  // the step bends too much for its second-order model: a rejected step
          continue;
        }
        step += 0.5 * a;
      }
      Eigen::MatrixX3d Pn = moved(P, free, step);
      const double Hn = vt ? H + step(np) : H;
      Eigen::VectorXd rn;
      double phin = std::numeric_limits<double>::infinity();
      if (!vt || restore_volume(*vt, Pn, free)) {
        f.residuals(Pn, Hn, &rn);
        phin = rn.squaredNorm();
      }
      const double pred = -(2.0 * g.dot(d) + d.dot(A * d));
      if (std::isfinite(phin) && phin < phi) {
        const double rho = pred > 0 ? (phi - phin) / pred : 0.0;
        if (rho > 0.75) lambda = std::max(lambda / 5, 1e-15);
        if (rho < 0.25) lambda *= 3;
        P = Pn;
        H = Hn;
        accepted = true;
      } else {
        lambda *= 10;
      }
    }
    if (!accepted) {
      out.stop = LsStop::NoStep;
      break;
    }
    ++out.iterations;
    evaluate(f, P, free, H, vt, r, J);
    phi = r.squaredNorm();
    report(progress, "cmc least squares", ls_fraction(start, target, std::sqrt(phi)), 1);
    history.push_back(phi);
    if (history.size() > 11) history.erase(history.begin());
    if (stalled(history) && std::sqrt(phi) > target) {
      out.stop = LsStop::Stalled;
      break;
    }
  }
  report(progress, "cmc least squares", 1, 1);
  return out;
}

}  // namespace

// Levenberg–Marquardt on Φ(P) = ‖r‖² over the free rows of P (in place), until √Φ <= target, a
// stall, no step, or max_iterations. A trial step is taken only when it and the new Φ are finite.
// Progress (stage "cmc least squares"): the fraction of the way from the start's √Φ to the target
// on a log scale, reported after every iteration, and 1 at the end.
LsOutcome minimise_newton(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free,
                          double H, double target, int max_iterations, bool geodesic, const ProgressFn& progress) {
  return lm_loop(f, P, free, H, nullptr, target, max_iterations, geodesic, progress);
}

namespace {

template <class Net>
CmcResult<Net> solve_mean_curvature_impl(const Net& data, const CmcOptions& o) {
  CmcResult<Net> res;
  res.functional = CmcFunctionalKind::MeanCurvature;
  {
    ScopedTimer timer(res.summary.seconds);
    o.validate();
    // The start: the paper's D_H critical point at H (or the last point of its branch), by the
    // newton continuation whatever o.solver (which picks the least-squares minimiser); in the V
    // form the minimiser of D at V = V0 (nlopt) and its multiplier H.
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    od.solver = o.V ? CmcSolver::NLopt : CmcSolver::Newton;
    const CmcResult<Net> start = solve_cmc(data, od);
    res.continuation_steps = start.continuation_steps;
    res.summary.iterations = start.summary.iterations;
    Eigen::MatrixX3d P = start.net.points();
    double H = o.V ? start.H : o.H;
    const std::vector<int> free = data.free_indices(o.fixed);
    const MeanCurvatureLeastSquares f = form_for(data, 0), check = form_for(data, 1);
    const auto cf = functional_for(data);
    // Minimised to 0.7 × the tolerance, so that the check rule (finer) does not miss it by its own small error.
    const double target = 0.7 * o.mean_curvature_tolerance;
    const bool ceres = o.solver == CmcSolver::Ceres;
    LsOutcome ls;
    std::optional<VolumeTarget> vt;
    if (o.V) {
      // The volume's scale: the size of its terms, |V0|, or the start's area^(3/2), whichever is
      // largest (a planar start through the origin has value_scale 0; so has V0 = 0).
      const double vscale = std::max({cf->volume_form().value_scale(P), std::abs(*o.V), std::pow(area(start.net), 1.5)});
      vt.emplace(VolumeTarget{cf->volume_form(), *o.V, vscale > 0 ? vscale : 1.0});
      ls = lm_loop(f, P, free, H, &*vt, target, o.max_least_squares_iterations, o.geodesic_acceleration, o.progress);
    } else if (ceres) {
      ls = minimise_ceres(f, P, free, H, target, o.max_least_squares_iterations, o.progress);
    } else {
      ls = minimise_newton(f, P, free, H, target, o.max_least_squares_iterations, o.geodesic_acceleration,
                           o.progress);
    }
    res.summary.iterations += ls.iterations;
    const Net net = make_net(data, P);
    res.net = net;
    res.H = H == 0.0 ? 0.0 : H;  // no "-0" in the report
    res.D = cf->dirichlet(P);
    res.V = cf->volume(P);
    res.DH = res.D + 2.0 * H * res.V;
    res.A = area(net);
    const double phi = check.value(P, H);
    res.energy = phi;
    res.quadrature_points = f.points_per_direction();
    res.summary.residual = std::sqrt(phi);
    const std::string start_note =
        o.V ? "from the minimiser of D at V = " + num(*o.V, 3) + " (H = " + num(start.H, 3) + ")"
        : start.summary.converged ? "from the D_H critical point at H = " + num(o.H, 3)
                                  : "from the last D_H branch point (H = " + num(start.H, 3) + ")";
    const std::string what = "least squares of the mean curvature " + start_note + ": √Φ = " +
                             num(res.summary.residual, 3) + (o.V ? " at H = " + num(H, 6) : std::string()) +
                             " after " + std::to_string(ls.iterations) +
                             (ceres ? " Ceres Levenberg–Marquardt iteration(s)" : " Levenberg–Marquardt iteration(s)");
    const double v_off = o.V ? std::abs(res.V - *o.V) / vt->scale : 0.0;
    const Regularity reg = regularity(net, res.A);
    if (!reg.ok) {
      res.summary.set_failed(Status::NoConvergence,
                             "degenerate parametrisation: |x_u ∧ x_v| falls to " + num(reg.min_ratio, 3) +
                                 " of its mean inside the patch" + (reg.flipped ? " and the normal flips" : "") +
                                 " (not a CMC surface); " + what);
    } else if (!(v_off <= o.tolerance)) {
      res.summary.set_failed(Status::NoConvergence,
                             what + ", but V misses V0 by " + num(v_off, 3) + " (relative): " +
                                 (ls.stop == LsStop::VolumeUnmet ? kVolumeUnmet : "above the tolerance"));
    } else if (!(res.summary.residual <= o.mean_curvature_tolerance)) {
      std::string why;
      switch (ls.stop) {
        case LsStop::Reached:
          why = " by the check rule (q = " + std::to_string(check.points_per_direction()) +
                "), although the rule minimised (q = " + std::to_string(f.points_per_direction()) +
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
        case LsStop::VolumeUnmet:
          why = std::string(": ") + kVolumeUnmet;
          break;
      }
      res.summary.set_failed(Status::NoConvergence,
                             what + " is above the tolerance " + num(o.mean_curvature_tolerance, 3) + why);
    } else {
      res.summary.message = what;
      res.summary.set_converged();
    }
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

}  // namespace bpde::cmc_detail
