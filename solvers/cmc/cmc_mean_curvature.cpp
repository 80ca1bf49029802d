// The least-squares mean-curvature functional of the cmc problem (cmc.h, "The least-squares
// mean-curvature functional"; docs/cmc.md, "Least squares of the mean curvature"): from the D_H
// critical point, Levenberg–Marquardt on Φ = ∫ ρ (H_x − H)² dA (mean_curvature_least_squares.h).
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <type_traits>

#include "bezierpde/core/progress.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/area_functional.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/cmc_area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/mean_curvature_least_squares.h"
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

// Why the Levenberg–Marquardt loop stopped.
enum class LsStop {
  Reached,        ///< √Φ <= its target on the rule minimised
  Stalled,        ///< Φ fell by less than 1e-6 (relative) in 10 iterations
  NoStep,         ///< no trial step lowered Φ (30 tries with growing damping)
  MaxIterations,  ///< options.max_least_squares_iterations used up
  NonFinite,      ///< Φ or its Jacobian is not finite at the current net
};

struct LsOutcome {
  int iterations = 0;
  LsStop stop = LsStop::MaxIterations;
};

// Levenberg–Marquardt on Φ(P) = ‖r‖² over the free rows of P (in place), until √Φ <= target, a
// stall, no step, or max_iterations. A trial step is taken only when it and the new Φ are finite.
// Progress (stage "cmc least squares"): the fraction of the way from the start's √Φ to the target
// on a log scale, reported after every iteration, and 1 at the end.
LsOutcome minimise(const MeanCurvatureLeastSquares& f, Eigen::MatrixX3d& P, const std::vector<int>& free, double H,
                   double target, int max_iterations, const ProgressFn& progress) {
  LsOutcome out;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  f.residuals(P, H, &r, &free, &J);
  double phi = r.squaredNorm(), lambda = 1e-3;
  std::deque<double> history{phi};
  const double start = std::sqrt(phi);
  auto fraction = [&] {
    const double span = std::log(start / target), f0 = span > 0 ? std::log(start / std::sqrt(phi)) / span : 1.0;
    return std::isfinite(f0) ? std::clamp(f0, 0.0, 0.999) : 0.0;
  };
  report(progress, "cmc least squares", 0, 1);
  const Eigen::Index n = J.cols();
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
    bool accepted = false;
    for (int tries = 0; tries < 30 && !accepted; ++tries) {
      Eigen::MatrixXd M = A;
      M.diagonal() += lambda * diag;
      const Eigen::LLT<Eigen::MatrixXd> llt(M);
      const Eigen::VectorXd d = llt.info() == Eigen::Success ? Eigen::VectorXd(-llt.solve(g)) : Eigen::VectorXd();
      if (d.size() != g.size() || !d.allFinite()) {
        lambda *= 10;
        continue;
      }
      Eigen::MatrixX3d Pn = P;
      for (size_t a = 0; a < free.size(); ++a) Pn.row(free[a]) += d.segment<3>(3 * Eigen::Index(a)).transpose();
      Eigen::VectorXd rn;
      f.residuals(Pn, H, &rn);
      const double phin = rn.squaredNorm(), pred = -(2.0 * g.dot(d) + d.dot(A * d));
      if (std::isfinite(phin) && phin < phi) {
        const double rho = pred > 0 ? (phi - phin) / pred : 0.0;
        if (rho > 0.75) lambda = std::max(lambda / 5, 1e-15);
        if (rho < 0.25) lambda *= 3;
        P = Pn;
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
    f.residuals(P, H, &r, &free, &J);
    phi = r.squaredNorm();
    report(progress, "cmc least squares", fraction(), 1);
    history.push_back(phi);
    if (history.size() > 11) history.pop_front();
    if (history.size() == 11 && history.front() - phi < 1e-6 * history.front() && std::sqrt(phi) > target) {
      out.stop = LsStop::Stalled;
      break;
    }
  }
  report(progress, "cmc least squares", 1, 1);
  return out;
}

template <class Net>
CmcResult<Net> solve_mean_curvature_impl(const Net& data, const CmcOptions& o) {
  CmcResult<Net> res;
  res.functional = CmcFunctionalKind::MeanCurvature;
  {
    ScopedTimer timer(res.summary.seconds);
    o.validate();
    // The start: the paper's D_H critical point at H (or the last point of its branch).
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    const CmcResult<Net> start = solve_cmc(data, od);
    res.continuation_steps = start.continuation_steps;
    res.summary.iterations = start.summary.iterations;
    Eigen::MatrixX3d P = start.net.points();
    const std::vector<int> free = data.free_indices(o.fixed);
    const MeanCurvatureLeastSquares f = form_for(data, 0), check = form_for(data, 1);
    // Minimised to 0.7 × the tolerance, so that the check rule (finer) does not miss it by its own small error.
    const LsOutcome ls =
        minimise(f, P, free, o.H, 0.7 * o.mean_curvature_tolerance, o.max_least_squares_iterations, o.progress);
    res.summary.iterations += ls.iterations;
    const Net net = make_net(data, P);
    const auto cf = functional_for(data);
    res.net = net;
    res.H = o.H;
    res.D = cf->dirichlet(P);
    res.V = cf->volume(P);
    res.DH = res.D + 2.0 * o.H * res.V;
    res.A = area(net);
    const double phi = check.value(P, o.H);
    res.energy = phi;
    res.quadrature_points = f.points_per_direction();
    res.summary.residual = std::sqrt(phi);
    const std::string start_note = start.summary.converged
                                       ? "from the D_H critical point at H = " + num(o.H, 3)
                                       : "from the last D_H branch point (H = " + num(start.H, 3) + ")";
    const std::string what = "least squares of the mean curvature " + start_note + ": √Φ = " +
                             num(res.summary.residual, 3) + " after " + std::to_string(ls.iterations) +
                             " Levenberg–Marquardt iteration(s)";
    const Regularity reg = regularity(net, res.A);
    if (!reg.ok) {
      res.summary.set_failed(Status::NoConvergence,
                             "degenerate parametrisation: |x_u ∧ x_v| falls to " + num(reg.min_ratio, 3) +
                                 " of its mean inside the patch" + (reg.flipped ? " and the normal flips" : "") +
                                 " (not a CMC surface); " + what);
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
