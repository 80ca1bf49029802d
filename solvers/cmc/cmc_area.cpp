// The area functional of the cmc problem (cmc.h, "The area functional"): critical points of
// A_H = A + 2HV and the volume-constrained minimum of A, by a regularised Newton method.
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/kron.h"
#include "bezierpde/solvers/cmc/area_rule.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/cmc_area_problem.h"
#include "bezierpde/solvers/summary.h"

namespace bpde::cmc_detail {
namespace {

Eigen::VectorXd to_vector(const Eigen::MatrixX3d& G) {
  Eigen::VectorXd g(3 * G.rows());
  for (Eigen::Index a = 0; a < G.rows(); ++a) g.segment<3>(3 * a) = G.row(a).transpose();
  return g;
}

}  // namespace

double AreaProblem::value(double H) const {
  double f = a->value(base.P) + 2.0 * H * base.f->volume(base.P);
  if (eps != 0.0) f += eps * (base.f->dirichlet(base.P) - a->value(base.P));
  return f;
}

Eigen::VectorXd AreaProblem::gradient(double H) const {
  Eigen::VectorXd g;
  residual_at(H, eps, &g);
  return g;
}

Eigen::MatrixXd AreaProblem::hessian(double H) const {
  Eigen::MatrixXd K = a->hessian(base.P, base.free);
  if (eps != 0.0) K = (1.0 - eps) * K + eps * C;
  if (H != 0.0) K += 2.0 * H * base.f->volume_form().hessian(base.P, base.free);
  return K;
}

double AreaProblem::residual_at(double H, double e, Eigen::VectorXd* g) const {
  if (progress) report(*progress, "cmc area", progress_done, 1);
  Eigen::MatrixX3d G, S;
  a->gradient_rows_and_scale(base.P, base.free, &G, &S);
  if (e != 0.0) {
    const Eigen::MatrixXd Cf = base.f->gram()(base.free, Eigen::all);
    Eigen::MatrixX3d GD(G.rows(), 3), SD(G.rows(), 3);
    for (int c = 0; c < 3; ++c) {
      GD.col(c) = Cf * base.P.col(c);
      SD.col(c) = Cf.cwiseAbs() * base.P.col(c).cwiseAbs();
    }
    G = (1.0 - e) * G + e * GD;
    S = (1.0 - e) * S + e * SD;
  }
  if (H != 0.0) {
    Eigen::MatrixX3d GV, SV;
    base.f->volume_form().gradient_rows_and_scale(base.P, base.free, &GV, &SV);
    G += 2.0 * H * GV;
    S += 2.0 * std::abs(H) * SV;
  }
  if (g) *g = to_vector(G);
  if (G.size() == 0) return 0.0;
  const double nm = G.cwiseAbs().maxCoeff(), den = S.maxCoeff();
  if (!std::isfinite(nm) || !std::isfinite(den)) return std::numeric_limits<double>::infinity();
  if (den == 0.0) return nm == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return nm / den;
}

CorrectorStats area_newton_correct(AreaProblem& p, double H, const CmcOptions& o, int max_iterations, double& theta,
                                   double target) {
  // Levenberg–Marquardt on A_H: (K + μC) δ = -g, μ = θ r (r the relative residual, C the Dirichlet
  // Gram). The step is judged by the ratio ρ of the actual to the predicted change of A_H
  // (m(δ) = g·δ + ½ δᵀKδ): accepted when ρ > 0.1; θ falls ×4 when ρ > 0.75 and rises ×4 when
  // ρ < 0.25 (×10 on a rejection or when K + μC is not positive definite). Once the predicted
  // change is below the rounding noise of A_H (1e-13 of the size of its terms), the step is
  // accepted when it lowers the residual instead. The surface must stay regular at the nodes.
  CorrectorStats st;
  Eigen::VectorXd g;
  st.residual = p.residual(H, &g);
  double f = p.value(H);
  const double fscale = std::abs(p.area()) + 2.0 * std::abs(H) * std::abs(p.base.f->volume(p.P())) + 1e-300;
  int stalled = 0;
  std::vector<double> history{st.residual};
  for (int it = 0;; ++it) {
    if (!std::isfinite(st.residual)) return st;
    if (st.residual <= o.tolerance || (target > 0 && p.eps != 0.0 && p.residual_at(H, 0.0) <= target)) {
      st.ok = true;
      return st;
    }
    if (it >= max_iterations || stalled >= 4) return st;
    // An ε-stage (ε > 0) in the heavily damped regime (θ ≥ 1e4: the step is damped in every soft,
    // tangential mode) with the residual falling less than ×2 in 4 iterations: a linear crawl
    // along the valley (measured: 0.5 % per iteration at θ = 1e6, for up to 60 iterations). Stop
    // and let the homotopy change ε instead.
    if (p.eps != 0.0 && theta >= 1e4 && history.size() >= 5 && st.residual > 0.5 * history[history.size() - 5])
      return st;
    const Eigen::MatrixXd K = p.hessian(H);
    if (!K.allFinite()) return st;
    const Eigen::VectorXd y = p.get();
    bool accepted = false;
    for (int tries = 0; tries < 20 && !accepted; ++tries) {
      const double mu = theta * st.residual;
      Eigen::LLT<Eigen::MatrixXd> llt(K + mu * p.C);
      if (llt.info() != Eigen::Success) {
        theta *= 10;
        continue;
      }
      Eigen::VectorXd d = -llt.solve(g);
      if (!d.allFinite()) {
        theta *= 10;
        continue;
      }
      // Chord corrections with the same factor (at most 3, while the residual falls): they bring
      // a long step in the soft (tangential) directions back to the floor of the curved valley.
      p.set(y + d);
      Eigen::VectorXd gn;
      double rn = p.residual(H, &gn);
      for (int c = 0; c < 3 && std::isfinite(rn); ++c) {
        const Eigen::VectorXd dc = -llt.solve(gn);
        if (!dc.allFinite()) break;
        p.set(y + d + dc);
        Eigen::VectorXd gc;
        const double rc = p.residual(H, &gc);
        if (!(rc < rn)) {
          p.set(y + d);
          break;
        }
        d += dc;
        rn = rc;
        gn = gc;
      }
      const double pred = g.dot(d) + 0.5 * d.dot(K * d);
      const double fn = p.value(H);
      bool ok = std::isfinite(fn) && std::isfinite(rn) && p.a->min_normal(p.P()) > 0.0;
      double rho = 0.0;
      if (ok) {
        // A fall of the residual is always accepted; A_H must fall as predicted otherwise (while
        // the prediction is above the rounding noise of A_H).
        // (the Euclidean norm of the gradient: a short step along -(K + μC)^{-1} g always lowers it
        // when K is positive semidefinite, the max-norm of the residual not necessarily)
        const bool falls = gn.norm() < g.norm();
        rho = std::abs(pred) > 1e-12 * fscale ? (fn - f) / pred : 0.0;
        ok = falls || rho > 0.1;
        if (falls && !(rho > 0.1)) rho = 0.5;
      }
      if (ok) {
        accepted = true;
        stalled = rn < st.residual ? 0 : stalled + 1;
        if (rho == 0.5 && stalled > 0) stalled = 0;  // the gradient norm fell
        f = fn;
        g = gn;
        st.residual = rn;
        if (rho > 0.75) theta = std::max(theta / 4, 1e-8);
        if (rho < 0.25) theta *= 4;
      } else {
        p.set(y);
        theta *= 10;
      }
    }
    ++st.iterations;
    history.push_back(st.residual);
    if (!accepted) return st;
  }
}

// The soft-mode phase's iteration bound, in units of o.max_corrector_iterations (default 30: 300
// iterations; the circle at n = 10, H = -0.9 takes 21, docs/cmc.md "The soft-mode phase").
constexpr int kSoftModeIterationsPerCorrector = 10;

// How often the truncated Newton phase asks for the rule to be chosen again (AreaProblem::refresh_rule).
constexpr int kRuleRefreshEvery = 4;

CorrectorStats area_truncated_newton(AreaProblem& p, double H, const CmcOptions& o, int max_iterations) {
  // Newton on A_H (ε = 0) restricted to the well-conditioned part of the Hessian. K v = λ C v (C the
  // Dirichlet Gram, so the cut does not depend on how the free points are scaled), v_iᵀ C v_j = δ_ij;
  // the kept step is -Σ_{|λ_i| > c λ_max} (v_iᵀ g / λ_i) v_i (the least-C-norm Newton step in the span
  // of the kept modes), the dropped step the same sum over the soft (tangential) modes. Each
  // iteration tries the cuts c = 1e-5, ..., 1e-10 and the fractions t = 0, 0.003, ..., 1 of the
  // dropped step, each trial followed by up to 16 chord corrections in the kept modes (back to the floor of the
  // curved valley; ended by the second that does not lower ‖g‖), and keeps the trial with the smallest Euclidean norm of the gradient (the
  // max-norm residual can stall while it falls); it stops when none lowers it. Measured (docs/cmc.md):
  // the normal part goes in one or two steps, the soft part linearly (a few % to ~10 % a step).
  CorrectorStats st;
  const double e0 = p.eps;
  p.eps = 0.0;
  Eigen::VectorXd g;
  st.residual = p.residual(H, &g);
  // A rule chosen anew changes the discrete A_H: its first variation is measured again.
  auto refresh = [&] {
    if (p.refresh_rule && p.refresh_rule()) st.residual = p.residual(H, &g);
  };
  for (int it = 0; it < max_iterations && std::isfinite(st.residual) && st.residual > o.tolerance; ++it) {
    if (it > 0 && it % kRuleRefreshEvery == 0) {
      refresh();
      if (!(std::isfinite(st.residual) && st.residual > o.tolerance)) break;
    }
    const Eigen::MatrixXd K = p.hessian(H);
    if (!K.allFinite()) break;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, p.C);
    if (es.info() != Eigen::Success) break;
    const Eigen::VectorXd& lam = es.eigenvalues();
    const Eigen::MatrixXd& Vm = es.eigenvectors();
    const double lmax = lam.cwiseAbs().maxCoeff();
    if (!(lmax > 0) || !std::isfinite(lmax)) break;
    const Eigen::VectorXd c = Vm.transpose() * g;
    const Eigen::VectorXd y = p.get();
    // Merit: the Euclidean norm of the gradient (the max-norm residual can stall while it falls).
    double best = g.norm(), best_r = st.residual;
    Eigen::VectorXd best_y, best_g;
    for (double cut = 1e-5; cut >= 1e-10; cut *= 0.1) {
      Eigen::VectorXd kept = Eigen::VectorXd::Zero(y.size()), dropped = kept;
      std::vector<Eigen::Index> keep;
      for (Eigen::Index i = 0; i < lam.size(); ++i) {
        if (std::abs(lam(i)) > cut * lmax) {
          kept -= (c(i) / lam(i)) * Vm.col(i);
          keep.push_back(i);
        } else if (lam(i) != 0.0) {
          dropped -= (c(i) / lam(i)) * Vm.col(i);
        }
      }
      if (!kept.allFinite() || !dropped.allFinite()) continue;
      // The dropped (soft) modes by a fraction t of their Newton step, each trial followed by up
      // to three chord corrections in the kept modes, which bring it back to the floor of the
      // curved valley.
      for (double t : {0.0, 0.003, 0.01, 0.03, 0.1, 0.2, 0.4, 1.0}) {
        Eigen::VectorXd d = kept + t * dropped;
        double prev = std::numeric_limits<double>::infinity();
        int rises = 0;
        for (int chord = 0; chord <= 16; ++chord) {
          p.set(y + d);
          Eigen::VectorXd gn;
          // Not finite also where |x_u ∧ x_v| vanishes at a node (n̂ = N/|N|): such a trial is out.
          const double rn = p.residual(H, &gn);
          if (!std::isfinite(rn)) break;
          // The second chord correction that does not lower ‖g‖ ends the trial: past that the
          // corrections diverge in the soft modes (measured on the circle, the sphere patch and
          // the tensor catenoid: the same or lower end residuals in 1.2–2.8× less time, docs/cmc.md "Speed").
          if (gn.norm() >= prev && ++rises >= 2) break;
          prev = gn.norm();
          if (gn.norm() < best) {
            best = gn.norm();
            best_r = rn;
            best_y = p.get();
            best_g = gn;
          }
          const Eigen::VectorXd cn = Vm.transpose() * gn;
          for (Eigen::Index i : keep) d -= (cn(i) / lam(i)) * Vm.col(i);
        }
      }
    }
    ++st.iterations;
    if (best_y.size() == 0) {
      p.set(y);
      break;
    }
    p.set(best_y);
    g = best_g;
    st.residual = best_r;
  }
  if (std::isfinite(st.residual) && st.residual > o.tolerance) refresh();
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  if (!st.ok && std::isfinite(st.residual)) {
    // What the truncated phase leaves is in the soft modes: the soft-mode phase
    // (area_soft_mode_phase.cpp) eliminates the hard ones and solves the reduced system.
    const CorrectorStats soft = area_soft_mode_phase(p, H, o, kSoftModeIterationsPerCorrector * o.max_corrector_iterations);
    st.iterations += soft.iterations;
    st.soft_iterations = soft.iterations;
    st.trust_region_iterations = soft.trust_region_iterations;
    st.residual = soft.residual;
    st.ok = soft.ok;
    st.soft_stationary = soft.soft_stationary;
    st.trust_region_blocked = soft.trust_region_blocked;
  }
  p.eps = e0;
  return st;
}


// ---------------------------------------------------------------- regularity

namespace {
template <class Net>
Eigen::Vector3d normal_at(const Net& net, double u, double v) {
  return net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1));
}

// The corners, where |x_u ∧ x_v| may vanish (an edge's tangents meet at an angle the net cannot
// open): a barycentric coordinate (u, v, 1 − u − v) above 1 − 0.05 (triangular), or both u and v
// within 0.05 of 0 or 1 (tensor). The regularity test and normal_gap leave them out.
constexpr double kCornerMargin = 0.05;
bool near_corner(bool triangular, double u, double v) {
  if (triangular) return std::max({u, v, 1 - u - v}) > 1 - kCornerMargin + 1e-12;
  return std::min(u, 1 - u) < kCornerMargin - 1e-12 && std::min(v, 1 - v) < kCornerMargin - 1e-12;
}
}  // namespace

// Folds inside the corner margins, which the grid leaves out. On rays from each corner into the
// domain, (1 − a) d1 + a d2 (d1, d2 its edges, a = 0, 1/4, …, 1), at distances 0.05 · 4^-k
// (k = 0 … 7, down to 3e-6 of the edge), the normal must keep its direction: N · N' < 0 between
// a sample and the one at 0.05 on its ray, or between neighbouring rays at one distance, is a fold.
// A corner where the edges meet at 180° has N → 0 there but N ≈ r (a cos φ + b sin φ) along each
// ray, whose direction does not turn; a fold (the circle's arcs fitted at degree 4, which meet at
// 180.84°: docs/cmc.md, "The rule near nearly degenerate corners") turns it over.
template <class Net>
void corner_folds(const Net& net, double mean, const std::vector<std::array<double, 6>>& corners, Regularity& r) {
  constexpr int kRays = 4, kDepth = 7;
  for (const auto& c : corners) {
    std::vector<Eigen::Vector3d> outer(kRays + 1);
    bool fold = false;
    double mn = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kDepth; ++k) {
      const double d = kCornerMargin * std::ldexp(1.0, -2 * k);
      std::vector<Eigen::Vector3d> N(kRays + 1);
      for (int j = 0; j <= kRays; ++j) {
        const double a = double(j) / kRays;
        const double u = c[0] + d * ((1 - a) * c[2] + a * c[4]), v = c[1] + d * ((1 - a) * c[3] + a * c[5]);
        N[j] = normal_at(net, u, v);
        mn = std::min(mn, N[j].norm() / mean);
        if (k == 0) outer[j] = N[j];
        if (N[j].dot(outer[j]) < 0 || (j > 0 && N[j].dot(N[j - 1]) < 0)) fold = true;
      }
    }
    if (fold && r.fold_u < 0) {
      r.fold_u = c[0];
      r.fold_v = c[1];
      r.fold_min_ratio = mn;
      // The boundary's angle at the corner, on the side of the surface (its normal at 0.05 on the
      // middle ray): above 180° (reflex) the edges' tangents give a corner normal against it.
      const Eigen::Vector3d xu = net.derivative(c[0], c[1], 1, 0), xv = net.derivative(c[0], c[1], 0, 1);
      const Eigen::Vector3d t1 = c[2] * xu + c[3] * xv, t2 = c[4] * xu + c[5] * xv;
      const double det = c[2] * c[5] - c[3] * c[4];
      const double theta = std::atan2(t1.cross(t2).norm(), t1.dot(t2)) * 180 / std::numbers::pi;
      r.fold_corner_angle = t1.cross(t2).dot(outer[kRays / 2]) * det >= 0 ? theta : 360 - theta;
    }
  }
}

// |x_u ∧ x_v| on a 40 x 40 grid away from the corners (margin 0.05), relative to the mean A/|domain|.
Regularity regularity(const TriangularNet& net, double A) {
  const int Ns = 40;
  const double mean = A / 0.5;
  Regularity r;
  r.min_ratio = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> N(static_cast<size_t>((Ns + 1) * (Ns + 1)));
  std::vector<char> use(N.size(), 0);
  auto id = [&](int a, int b) { return static_cast<size_t>(a * (Ns + 1) + b); };
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns - a; ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (near_corner(true, u, v)) continue;
      N[id(a, b)] = normal_at(net, u, v);
      use[id(a, b)] = 1;
      r.min_ratio = std::min(r.min_ratio, N[id(a, b)].norm() / mean);
    }
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns - a; ++b) {
      if (!use[id(a, b)]) continue;
      if (a + 1 + b <= Ns && use[id(a + 1, b)] && N[id(a, b)].dot(N[id(a + 1, b)]) < 0) r.flipped = true;
      if (a + b + 1 <= Ns && use[id(a, b + 1)] && N[id(a, b)].dot(N[id(a, b + 1)]) < 0) r.flipped = true;
    }
  r.ok = std::isfinite(r.min_ratio) && r.min_ratio >= 1e-3 && !r.flipped;
  return r;
}

Regularity regularity(const TensorNet& net, double A) {
  const int Ns = 40;
  const double mean = A;
  Regularity r;
  r.min_ratio = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> N(static_cast<size_t>((Ns + 1) * (Ns + 1)));
  std::vector<char> use(N.size(), 0);
  auto id = [&](int a, int b) { return static_cast<size_t>(a * (Ns + 1) + b); };
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns; ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (near_corner(false, u, v)) continue;
      N[id(a, b)] = normal_at(net, u, v);
      use[id(a, b)] = 1;
      r.min_ratio = std::min(r.min_ratio, N[id(a, b)].norm() / mean);
    }
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns; ++b) {
      if (!use[id(a, b)]) continue;
      if (a < Ns && use[id(a + 1, b)] && N[id(a, b)].dot(N[id(a + 1, b)]) < 0) r.flipped = true;
      if (b < Ns && use[id(a, b + 1)] && N[id(a, b)].dot(N[id(a, b + 1)]) < 0) r.flipped = true;
    }
  r.ok = std::isfinite(r.min_ratio) && r.min_ratio >= 1e-3 && !r.flipped;
  return r;
}

// The corners (u, v) with their edges' directions (barycentric order: P_n00 at (1, 0), P_0n0 at
// (0, 1), P_00n at (0, 0); tensor: P_00, P_n0, P_nn, P_0n).
Regularity final_regularity(const TriangularNet& net, double A) {
  Regularity r = regularity(net, A);
  if (r.ok) {
    corner_folds(net, A / 0.5, {{1, 0, -1, 1, -1, 0}, {0, 1, 0, -1, 1, -1}, {0, 0, 1, 0, 0, 1}}, r);
    r.ok = r.fold_u < 0;
  }
  return r;
}

Regularity final_regularity(const TensorNet& net, double A) {
  Regularity r = regularity(net, A);
  if (r.ok) {
    corner_folds(net, A, {{0, 0, 1, 0, 0, 1}, {1, 0, -1, 0, 0, 1}, {1, 1, -1, 0, 0, -1}, {0, 1, 1, 0, 0, -1}}, r);
    r.ok = r.fold_u < 0;
  }
  return r;
}

std::string Regularity::describe() const {
  if (!(std::isfinite(min_ratio) && min_ratio >= 1e-3) || flipped || fold_u < 0)
    return "|x_u ∧ x_v| falls to " + num(min_ratio) + " of its mean inside the patch" +
           (flipped ? " and the normal flips" : "");
  return "the normal flips near the corner (u, v) = (" + num(fold_u, 1) + ", " + num(fold_v, 1) +
         ") (a fold inside the corner margin 0.05; |x_u ∧ x_v| down to " + num(fold_min_ratio, 3) +
         " of its mean there; the boundary's edges meet at " + num(fold_corner_angle, 6) + "°" +
         (fold_corner_angle > 180 ? " (reflex: the normal at the corner, which the edges fix, points against the surface's)"
                                  : "") +
         ")";
}

namespace {

// ---------------------------------------------------------------- the solve

// A corrector on A (H = 0) that stops above the tolerance but within this relative first variation
// is reported as a numerical limit (status numerical-limit, with the first variation reached), not
// as "no critical point": the ε-route of H ≠ 0 reports its stalled last stages the same way.
constexpr double kAreaStallResidual = 1e-6;

struct AreaOutcome {
  double H = 0.0;
  bool ok = false;
  Status why = Status::NoConvergence;
  std::string message;
};

bool is_triangular(const TriangularNet&) { return true; }
bool is_triangular(const TensorNet&) { return false; }

// The samples of normal_gap: the points (a/10, b/10) of the domain (66 on the triangle, 121 on
// the square) without the corners (near_corner).
std::vector<Eigen::Vector2d> gap_samples(bool triangular) {
  const int Ns = 10;
  std::vector<Eigen::Vector2d> uv;
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= (triangular ? Ns - a : Ns); ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (!near_corner(triangular, u, v)) uv.emplace_back(u, v);
    }
  return uv;
}

// normal_gap (cmc_area_problem.h) for both nets.
template <class Net>
double normal_gap_on(const Net& a, const Net& b) {
  double gap = 0.0;
  for (const Eigen::Vector2d& uv : gap_samples(is_triangular(a))) {
    const Eigen::Vector3d N = normal_at(a, uv[0], uv[1]);
    const double len = N.norm();
    if (!(len > 0)) return std::numeric_limits<double>::infinity();
    gap = std::max(gap, std::abs((b.evaluate(uv[0], uv[1]) - a.evaluate(uv[0], uv[1])).dot(N)) / len);
  }
  return gap;
}

}  // namespace

double normal_gap(const TriangularNet& a, const TriangularNet& b) { return normal_gap_on(a, b); }
double normal_gap(const TensorNet& a, const TensorNet& b) { return normal_gap_on(a, b); }

namespace {

// Route 0's limits (AreaSolve::from_mean_curvature): the iterations of the H form's least squares
// (or max_least_squares_iterations when lower; the V form's has max_least_squares_iterations: past
// the hemisphere its continuation in V takes 800–1100), and the Newton iterations on A_H from it.
// Measured on the tensor catenoid (docs/cmc.md, "The mean-curvature start"): its least squares
// converge slowly (n = 12: √Φ 2.3e-6 after 300 iterations, 1e-6 after 1200), but from where they
// are after 300 the Newton iterations and the final phases converge (n = 12 in 3.2 s, where
// 1200 took 10.8 s; n = 8 4.9 s, with 150 6.4 s).
constexpr int kMeanCurvatureStartIterations = 300;
constexpr int kMeanCurvatureStartCorrector = 8;
// Route 0 is not tried where the relative first variation of A_H at the D_H critical point is at
// most this (AreaSolve::dirichlet_first_variation): on the conformal sphere triangle 8.2e-7 at
// n = 10 and below from there on, on the Fig. 1 circle 7e-2.
constexpr double kConformalFirstVariation = 1e-6;
// The relative first variation each step of the H and V continuations is corrected to (the
// tolerance when that is looser); the end point is then corrected to the tolerance.
constexpr double kContinuationStepTolerance = 1e-8;


template <class Net>
struct AreaSolve {
  const Net& data;
  const CmcOptions& o;
  AreaProblem p;
  bool tri;
  int n, m;
  double theta = 1.0;
  Summary& summary;

  // The paper's D_H critical point at H by the newton continuation (with V0: the minimiser of D at
  // V = V0 by nlopt), solved once for the last (H, V0) asked: the test before route 0, route 0's
  // least squares (their start) and the routes from the D_H point ask for the same one (the nlopt
  // minimiser costs up to 0.17 s at n = 12; sharing it saves 0.06 and 0.15 s of 0.44 and 2.9 s on
  // the V form's smaller and larger caps of H = −0.9 and −0.7 at n = 12, measured).
  std::optional<std::pair<std::pair<double, std::optional<double>>, CmcResult<Net>>> dirichlet_cache;
  const CmcResult<Net>& dirichlet_solution(double H, const double* V0) {
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

  // Rule chosen at the current net with the rule tolerance (0.1 x the residual tolerance).
  bool choose_rule(int start_q = 0, int start_grading = 1, int start_levels = 0) {
    return choose_rule_for(o.tolerance, start_q, start_grading, start_levels);
  }
  // The rule checked at the current net and refined from the rule in use (never coarser).
  bool refine_rule() {
    const std::shared_ptr<const AreaForm> a = p.a;
    return choose_rule(a->points_per_direction(), a->grading(), a->levels());
  }
  double rule_change = 0.0;  ///< the measured error of the rule last chosen

  // Rule chosen at the current net for a corrector run to the residual tolerance `tol` (rule
  // tolerance 0.1 tol). Each ε-stage chooses its own (stage tolerances 1e-6 … 5e-12), the jump to
  // ε = 0 the full one: the early stages need far fewer nodes, and the Hessian's cost is linear
  // in the nodes. (Circle n = 16: the D_H start needs q = 27 for 1e-12, the final net q = 20.)
  // The final rule check in solve_area_impl refines on the final net when needed.
  bool choose_rule_for(double tol, int start_q = 0, int start_grading = 1, int start_levels = 0) {
    const AreaRule r =
        choose_area_rule(tri, n, m, p.P(), p.base.free, 0.1 * tol, start_q, start_grading, start_levels);
    p.a = r.form;
    rule_change = r.change;
    return r.ok;
  }

  // The residual at which the last final phase ended at a stationary point of the reduced first
  // variation's norm (area_soft_mode_phase.cpp), else -1. The messages say so only when the net
  // reported is still that point (the same residual: it is a function of the net and the rule) and
  // in the H form (the V form's residual includes the volume).
  double stationary_at = -1.0;
  // The same for an end where the trust-region part of the soft-mode phase stopped at its
  // regularity bound (its descent on A_H heads for a degenerate parametrisation).
  double degenerate_at = -1.0;

  // What a route changes in the solve: the net, the rule and its measured error, the damping, the
  // regulariser and the soft-mode verdict. A route that is tried and not kept puts them back
  // (save() before it, restore() after), and the end of one route kept for later is one of these.
  struct State {
    Eigen::MatrixX3d P;
    std::shared_ptr<const AreaForm> a;
    double theta = 1.0, rule_change = 0.0, eps = 0.0, stationary_at = -1.0, degenerate_at = -1.0;
  };
  State save() const { return {p.base.P, p.a, theta, rule_change, p.eps, stationary_at, degenerate_at}; }
  void restore(const State& s) {
    p.base.P = s.P;
    p.a = s.a;
    theta = s.theta;
    rule_change = s.rule_change;
    p.eps = s.eps;
    stationary_at = s.stationary_at;
    degenerate_at = s.degenerate_at;
  }

  // Where route 0 ended in the H form above the tolerance but within kAreaStallResidual, at a
  // regular net whose rule met its own at its start (a numerical limit of its own): that end, for
  // the caller to keep when the routes from the D_H critical point end higher (keep_route0_end).
  struct RouteEnd {
    State state;
    std::string note;
  };
  std::optional<RouteEnd> route0_end;

  // The residual at H (the relative first variation of A_H; in the V form vresidual, with the
  // volume) with a rule that meets its tolerance at the current net (refined from the rule in use,
  // never coarser, as the final rule check); the rule in use is put back. +inf when not finite.
  double checked_residual(double H) {
    const std::shared_ptr<const AreaForm> a = p.a;
    const double change = rule_change;
    refine_rule();
    const double r = o.V ? vresidual(*o.V, H) : p.residual_at(H, 0.0);
    p.a = a;
    rule_change = change;
    return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
  }

  // After the routes from the D_H critical point (H form), where they end above the tolerance or
  // fail: route 0's end instead when it has the lower residual, both on checked rules (measured:
  // the tensor catenoid at n = 10, 2.6e-11 against 5.2e-11; docs/cmc.md, "The mean-curvature
  // start"). True when it was taken (net, rule, soft-mode verdict); `why` says what the other ended at.
  bool keep_route0_end(const AreaOutcome& out, std::string& why) {
    if (!route0_end) return false;
    const double r_dh = out.ok ? checked_residual(o.H) : std::numeric_limits<double>::infinity();
    if (!(r_dh > o.tolerance)) return false;
    const State theirs = save();
    restore(route0_end->state);
    const double r0 = checked_residual(o.H);
    if (r0 < r_dh && r0 <= kAreaStallResidual) {
      p.eps = 0.0;  // A_H itself, as route 0 ended (the other routes may have stopped at ε > 0)
      theta = 1e-3;
      why = out.ok ? "the routes from the D_H critical point ended at " + num(r_dh, 3) + ": " + out.message
                   : "the routes from the D_H critical point failed: " + out.message;
      return true;
    }
    restore(theirs);
    return false;
  }

  bool at_stationary_point(double residual) const {
    return !o.V && stationary_at > 0 && std::abs(residual - stationary_at) <= 1e-12 * stationary_at;
  }
  bool at_degenerate_bound(double residual) const {
    return !o.V && degenerate_at > 0 && std::abs(residual - degenerate_at) <= 1e-12 * degenerate_at;
  }
  // The words for an end at one of the two: "" otherwise.
  std::string soft_verdict(double residual, bool long_form) const {
    std::string v;
    if (at_stationary_point(residual))
      v = long_form ? "; no step over the soft (tangential) modes lowers it (a stationary point of its norm there, "
                      "not a critical point of A_H)"
                    : ", where no step over the soft (tangential) modes lowers it";
    if (at_degenerate_bound(residual))
      v += "; the trust-region descent on A_H from there heads for a degenerate parametrisation (|x_u ∧ x_v| "
           "below a quarter of its smallest value at the start), so the net is the one it started from";
    return v;
  }
  // Whether finish() may choose the rule again (off in the final rule check, which only refines).
  bool choose_rules_again = true;
  // The final phases at ε = 0: newton, the truncated Newton phase, which ends in the soft-mode
  // phase; ceres, the soft-mode phase (by Ceres) alone. A caller that gives up their end puts
  // back the rule too (finish may have chosen another).
  CorrectorStats finish(double H, int max_iterations) {
    CorrectorStats t;
    // The rule chosen again where it missed its tolerance at the net where it was chosen: a start
    // that nearly folds at a corner (on a wavy boundary curve the Dirichlet extremal takes the
    // graded q = 64 rule, 32 768 nodes on a tensor net, and still misses by 1.7e-4) would otherwise
    // keep that rule through the final phases, the longest part of a hard solve, where the surface
    // reached needs far fewer nodes (there the plain q = 26 rule, 5408: docs/performance.md,
    // section 13). Here, and during the truncated Newton phase, where the net moves on from here.
    p.refresh_rule = [this] {
      if (!choose_rules_again || rule_change <= 0.1 * o.tolerance) return false;
      const std::shared_ptr<const AreaForm> a0 = p.a;
      choose_rule();
      return p.a != a0;
    };
    p.refresh_rule();
    if (o.solver == CmcSolver::Ceres) {
      t = area_soft_mode_phase(p, H, o, kSoftModeIterationsPerCorrector * o.max_corrector_iterations);
      t.soft_iterations = t.iterations;
    } else {
      t = area_truncated_newton(p, H, o, max_iterations);
    }
    p.refresh_rule = nullptr;
    stationary_at = t.soft_stationary ? t.residual : -1.0;
    degenerate_at = t.trust_region_blocked ? t.residual : -1.0;
    return t;
  }

  // "the truncated Newton phase [in N iteration(s)] and the soft-mode phase [in M]": what finish()
  // ran, for the messages.
  static std::string final_phases(const CorrectorStats& t, bool counts) {
    const int truncated = t.iterations - t.soft_iterations;
    auto phase = [&](const char* name, int it) {
      return std::string(name) + (counts ? " in " + std::to_string(it) + " iteration(s)" : "");
    };
    std::string s = truncated > 0 ? phase("the truncated Newton phase", truncated) : "";
    if (t.soft_iterations > 0) s += (s.empty() ? "" : " and ") + phase("the soft-mode phase", t.soft_iterations);
    if (t.trust_region_iterations > 0)
      s += counts ? " (" + std::to_string(t.trust_region_iterations) + " of them trust-region steps on A_H)"
                  : " (with trust-region steps on A_H)";
    return s;
  }

  // The corrector to `tol` (at least the tolerance; the continuation's steps pass a looser one),
  // then where it stalls the final phases, which aim at the tolerance itself: on the circle past
  // H = −0.8 (n = 6 and 8) the steps whose final phases stopped at 1e-8 left points from which
  // the next steps' Hessians were not positive definite or whose corrections moved along the
  // surface by as much as the step, and the continuation ended at H ≈ −0.85 and −0.96 instead of
  // the hemisphere.
  CorrectorStats correct(double H, double tol) {
    CmcOptions co = o;
    co.tolerance = std::max(tol, o.tolerance);
    CorrectorStats st = o.solver == CmcSolver::Ceres ? ceres_correct(p, H, co)
                                      : area_newton_correct(p, H, co, 2 * o.max_corrector_iterations, theta, 0.0);
    if (!st.ok && p.eps == 0.0 && std::isfinite(st.residual)) {
      // The corrector stalls in the tangential valley: finish with the final phases.
      const CorrectorStats t = finish(H, o.max_corrector_iterations);
      st.iterations += t.iterations;
      st.ok = t.ok || t.residual <= co.tolerance;
      st.residual = t.residual;
    }
    summary.iterations += st.iterations;
    return st;
  }

  // A strict local minimum of A_H, before the fold of the branch: K + σC positive definite, with
  // σ = 1e-4 × max_i K_ii / C_ii (a Rayleigh quotient, so at most the largest eigenvalue of
  // K v = λ C v; 1e-4 is the soft-mode phase's split of soft and hard modes) against the nearly
  // singular tangential modes. Those are not all positive: on the circle at n = 6 the two softest
  // are −1.0e-8 and −0.9e-8 of C (λ_max 1.31) all along the branch from H = −0.62 on, and the
  // shift 1e-8 C used before stopped the continuation there; on the helicoid piece at n = 6 a
  // cluster of them lies at −5e-7 … −2e-8 λ_max from H ≈ −0.06 on, where σ = 1e-6 × max K_ii/C_ii
  // stopped it; at n = 10 on the circle about 20 soft modes lie at −6e-9 … −2e-12 λ_max
  // (docs/cmc.md, "Not done yet"). A fold is where a mode of the surface's normal motion
  // crosses 0; past it the corrector finds no point.
  bool strict_minimum(double H, Eigen::VectorXd* tangent) {
    Eigen::MatrixXd K = p.hessian(H);
    if (!K.allFinite()) return false;
    const double scale = K.diagonal().cwiseQuotient(p.C.diagonal()).maxCoeff();  // C's diagonal > 0 (a Gram)
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    K += 1e-4 * scale * p.C;
    Eigen::LLT<Eigen::MatrixXd> llt(K);
    if (llt.info() != Eigen::Success) return false;
    if (tangent) *tangent = -2.0 * llt.solve(p.volume_gradient());
    return true;
  }

  // The vanishing Dirichlet regulariser: from a critical point of F_1 = D_H in p (and H), solve
  // F_ε = A_H + ε(D - A) for ε = 1, 1/10, 1/100, ... (each stage by `stage`, started from the
  // Euler predictor along the ε-path from the previous stage's point) until the first variation of
  // A_H itself meets the tolerance; after each stage with ε <= 1e-4 the jump to ε = 0 is tried
  // (jump()); ε then drops to 0 for a last stage. A failed stage is retried with a ratio closer to 1 (√ of the
  // last); successful ones square the ratio again (not below 1/100). F_ε is well conditioned in the
  // tangential directions for ε > 0, where A_H alone is nearly singular. With V0 (the V form) the
  // stages hold V = *V0 and move H (stage(H, ε) updates it), the predictor is the bordered one and
  // the jump corrects with the bordered corrector; ε below 1e-12 (not 1e-16) goes to 0, and when
  // the stages stop below ε = 1e-4 the last stage at ε = 0 is still tried (measured on the circle
  // when the two loops were merged: with the H form's rules the V form missed the tolerance at
  // n = 6, H = −0.9 (first variation 3.8e-8) and n = 10, H = −0.5 (1.1e-11), which converge as the
  // table in docs/cmc.md, "The V form on the circle", has them).
  template <class Stage>
  bool homotopy(double& H, Stage stage, std::string& note, const double* V0 = nullptr) {
    const bool fixed_volume = V0 != nullptr;
    double eps = 1.0, ratio = 0.1;
    int failures = 0;
    p.eps = eps;
    if (!stage(H, eps)) {
      note = "the start is not a critical point of D_H";
      return false;
    }
    // Progress (stage "cmc area"): the decades of ε removed, out of 12; 1 when the solve ends.
    p.progress_done = 0.0;
    report(o.progress, "cmc area", 0, 1);
    while (true) {
      if (p.residual_at(H, 0.0) <= o.tolerance || eps == 0.0) break;
      double next = eps * ratio;
      if (next < (fixed_volume ? 1e-12 : 1e-16)) next = 0.0;
      const Eigen::VectorXd y = p.get();
      const double Hs = H;
      predict(H, eps, next, fixed_volume);
      p.eps = next;
      const bool sok = stage(H, next);
      if (sok) {
        eps = next;
        ratio = std::max(ratio * ratio, 1e-2);
        p.progress_done = std::max(p.progress_done, eps > 0.0 ? std::min(0.999, std::log10(1.0 / eps) / 12.0) : 0.999);
        report(o.progress, "cmc area", p.progress_done, 1);
        if (eps <= 1e-4 && p.residual_at(H, 0.0) > o.tolerance && jump(H, eps, V0)) {
          eps = 0.0;
          break;
        }
      } else {
        p.set(y);
        H = Hs;
        p.eps = eps;
        ratio = std::sqrt(ratio);
        if (ratio > 0.7 || ++failures > 12) {
          // Keep the last stage: its first variation of A_H is ≈ ε |∇(D - A)| (reported by the
          // caller as a numerical limit when above the tolerance).
          note = "the Dirichlet regulariser could not be removed below ε = " + num(eps);
          if (fixed_volume && eps <= 1e-4) break;  // the V form tries the last stage below
          p.eps = 0.0;
          return eps <= 1e-4;
        }
      }
    }
    p.eps = 0.0;
    if (p.residual_at(H, 0.0) <= o.tolerance || (fixed_volume && eps == 0.0)) return true;
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

  // The jump to ε = 0 from a critical point of F_ε (ε ≤ 1e-4): the Euler predictor to ε = 0, then at most
  // 8 corrector iterations on A_H itself. Kept when they reach the tolerance; otherwise the point
  // goes back to the F_ε critical point and the stages go on. Measured (docs/cmc.md, "Final
  // convergence"): the predictor puts the start of the A_H corrector inside its basin, where the
  // stages alone (no predictor) stopped at ε ≈ 1e-8 … 1e-6 with the first variation at 1e-9 … 1e-7.
  // With V0 (the V form): the bordered predictor, and the bordered corrector, which moves H too
  // (restored with the net when the jump is not kept).
  bool jump(double& H, double eps, const double* V0 = nullptr) {
    const Eigen::VectorXd y = p.get();
    const double Hs = H;
    const std::shared_ptr<const AreaForm> a0 = p.a;
    predict(H, eps, 0.0, V0 != nullptr);
    p.eps = 0.0;
    choose_rule();
    CorrectorStats st;
    if (V0) {
      theta = 1e-8;
      st = bordered_correct(*V0, H, o.tolerance, 8);
      st.iterations = 0;  // bordered_correct counts its own into summary
    } else if (o.solver == CmcSolver::Ceres) {
      CmcOptions co = o;
      co.max_corrector_iterations = 8;
      st = ceres_correct(p, H, co);
    } else {
      double th = 1e-8;
      st = area_newton_correct(p, H, o, 8, th, 0.0);
    }
    summary.iterations += st.iterations;
    if (st.ok) return true;
    p.set(y);
    H = Hs;
    p.eps = eps;
    p.a = a0;
    return false;
  }

  // Euler predictor along the ε-path: dY/dε = -K_ε^{-1} ∇(D - A), from the current point (a critical
  // point of F_ε) to ε = next. With fixed_volume (the V form, H varies): from a critical point of
  // F_ε + 2HV with V = V0, the bordered system [K_ε 2∇V; ∇Vᵀ 0][dY; dH] = [−∇(D − A); 0], and H
  // moves too. Left unchanged when the predicted net is not regular.
  void predict(double& H, double eps, double next, bool fixed_volume = false) {
    const Eigen::VectorXd y = p.get();
    const double e0 = p.eps;
    p.eps = eps;
    Eigen::VectorXd g1, g0;
    p.residual_at(H, 1.0, &g1);
    p.residual_at(H, 0.0, &g0);
    const Eigen::MatrixXd K = p.hessian(H);
    p.eps = e0;
    const Eigen::LDLT<Eigen::MatrixXd> f(K);
    Eigen::VectorXd dy = -f.solve(g1 - g0);
    double dH = 0.0;
    if (fixed_volume) {
      const Eigen::VectorXd gV = p.volume_gradient(), b = f.solve(gV);
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

  // The stage tolerance: the F_ε residual that keeps the A_H residual (≈ ε |∇(D - A)|) on track.
  CmcOptions stage_options(double e) const {
    CmcOptions so = o;
    so.tolerance = std::max(0.5 * o.tolerance, std::min(1e-6, 1e-3 * e));
    return so;
  }

  // A at H = 0 from the net in p (the Dirichlet extremal), to `tol` (the tolerance; the start of
  // the H continuation needs only its steps' tolerance).
  bool minimal_surface(double tol) {
    choose_rule();
    return correct(0.0, tol).ok;
  }

  // H mode, route 1: the D_H critical point at H, corrected on A_H.
  bool from_dirichlet(double H, std::string& note) {
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
          double th = 1e-3;
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

  // H mode, route 2: continuation in H on A_H from the critical point of A at H = 0.
  AreaOutcome continuation(const Eigen::MatrixX3d& start, const std::vector<int>& fixed_idx, int& steps) {
    const double Ht = o.H;
    p.base.P = start;
    // The start needs only the steps' tolerance: on the tensor catenoid at n = 6 the critical
    // point of A stops at 1.2e-10 (a stationary point in the soft modes), and the continuation
    // was refused as "no critical point of the area (H = 0)".
    if (!minimal_surface(kContinuationStepTolerance))
      return {0.0, false, Status::NoConvergence, "no critical point of the area (H = 0) from the Dirichlet extremal"};
    Eigen::VectorXd tangent;
    if (!strict_minimum(0.0, &tangent))
      return {0.0, false, Status::NoConvergence, "the critical point of the area at H = 0 is not a strict minimum"};
    Eigen::VectorXd y = p.get();
    Net at = make_net(data, p.P());
    // The rule at y: a rejected step puts it back with the net (its final phases may have chosen
    // another at the rejected net).
    std::shared_ptr<const AreaForm> rule_at_y = p.a;
    double change_at_y = rule_change;
    StepController control(Ht, first_step(Ht, p.P(), fixed_idx), o);
    std::string rejected;  // why the last step was rejected, for the fold message
    while (!control.reached_target()) {
      if (!control.attempt())
        return {control.h(), false, Status::NoConvergence,
                "A_H continuation stopped at H ≈ " + num(control.h()) +
                    " after max_continuation_steps = " + std::to_string(o.max_continuation_steps) + " attempts"};
      const StepController::Step step = control.propose();
      const bool last = step.hn == Ht;
      const Eigen::VectorXd pred = y + tangent * step.s;
      p.set(pred);
      const Net predicted = make_net(data, p.P());
      // Every step, the last one too, is corrected to 1e-8 (relative first variation; the
      // tolerance if looser), as in the volume continuation, and the end point once more to the
      // tolerance after the loop: on the circle at n = 8 the steps' correctors stalled at
      // 1.0e-11 … 1.04e-11 against 1e-11 from H ≈ −0.9 on, and the step control took that for
      // the fold. A stall of the final correction is a numerical limit, which the solve's end
      // check reports as such.
      const CorrectorStats st = correct(step.hn, kContinuationStepTolerance);
      const Net now = make_net(data, p.P());
      // On the branch when the corrected point lies nearer the prediction than half its distance
      // from the last point, both measured along the surface normals (normal_gap), as in the
      // volume continuation: the corrector also moves the points along the surface, in the nearly
      // singular tangential modes, by as much as the step itself. The point test of the D_H
      // continuation (on_branch) rejected every step on the circle at n = 6 down to a step of
      // 9e-5 from H = 0 (the planar minimal surface, where the tangential modes are exactly
      // singular), though each corrector converged at a strict minimum of A_H.
      const double dev = normal_gap(predicted, now), move = normal_gap(at, now);
      Eigen::VectorXd next;
      const bool near_prediction = st.ok && std::isfinite(move) && dev <= 0.5 * move + 1e-12 * std::max(1.0, y.norm());
      const bool minimum = near_prediction && strict_minimum(step.hn, last ? nullptr : &next);
      rejected = !st.ok           ? "its corrector stopped at a relative first variation of " + num(st.residual, 3)
                 : !near_prediction ? "the corrected surface left the branch"
                              : "the Hessian there is not positive definite beyond the soft modes";
      if (minimum) {
        y = p.get();
        at = now;
        rule_at_y = p.a;
        change_at_y = rule_change;
        if (!last) tangent = next;
        ++steps;
        control.accept(step, st.iterations);
      } else {
        p.set(y);
        p.a = rule_at_y;
        rule_change = change_at_y;
        if (!control.reject(step))
          return {control.h(), false, Status::Fold,
                  "no critical point of A_H on the branch from H = 0 beyond H ≈ " + num(control.h()) +
                      " (at the last step tried, " + rejected + ")"};
      }
    }
    correct(Ht, o.tolerance);
    return {Ht, true, Status::Converged,
            "A_H continued from H = 0 to H = " + num(Ht) + " in " + std::to_string(steps) + " step(s)"};
  }

  // V mode: bordered regularised Newton on (Y, H) for ∇F_ε + 2H∇V = 0, V = V0, at fixed V0 (F_ε
  // = A + ε(D − A) at the current p.eps; ε = 0: A itself), to the relative residual `tol` (default:
  // o.tolerance).
  CorrectorStats bordered_correct(double V0, double& H, double tol = -1.0, int max_iterations = -1) {
    if (tol < 0) tol = o.tolerance;
    if (max_iterations < 0) max_iterations = 2 * o.max_corrector_iterations;
    CorrectorStats st;
    const VolumeForm& vf = p.base.f->volume_form();
    auto resid = [&](double h, Eigen::VectorXd& g, double& c) {
      const double rg = p.residual(h, &g);
      c = vf.value(p.P()) - V0;
      const double vs = vf.value_scale(p.P());
      return std::max(rg, vs > 0 ? std::abs(c) / vs : std::abs(c));
    };
    if (o.solver == CmcSolver::Ceres) {  // the same residuals and stopping measure, Ceres's LM
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
      for (int tries = 0; tries < 16 && !accepted; ++tries) {
        const SymFactor fac(K + theta * st.residual * p.C);
        const Eigen::VectorXd a = fac.solve(g), b = fac.solve(gV);
        const double den = 2.0 * gV.dot(b);
        if (!(std::abs(den) > 0) || !a.allFinite() || !b.allFinite()) {
          theta *= 10;
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
          theta = std::max(theta / 4, 1e-6);
        } else {
          p.set(y);
          theta *= 10;
        }
      }
      ++st.iterations;
      summary.iterations += 1;
      if (!accepted) return st;
    }
  }

  // The V form's residual at ε = 0: the larger of the relative first variation of A_H and |V − V0|
  // relative to the volume's scale (as the report computes it).
  double vresidual(double V0, double H) const {
    const double vs = p.base.f->volume_form().value_scale(p.P());
    return std::max(p.residual_at(H, 0.0), std::abs(p.base.f->volume(p.P()) - V0) / (vs > 0 ? vs : 1.0));
  }

  // V mode, route 1 (the V form of from_dirichlet): the minimiser of D at V = V0 (the nlopt route,
  // a critical point of F_1 = D + 2HV at V0 with its multiplier H), then the vanishing Dirichlet
  // regulariser at fixed V0: F_ε for ε = 1, 1/10, 1/100, … (ratio adapted as in homotopy()), each
  // stage by the bordered corrector from the bordered Euler predictor, until the first variation
  // of A_H itself meets the tolerance, then ε = 0. Route 3 (volume_continuation, from the critical
  // point of A at H = 0) fails on non-conformal data: that start is planar on planar boundaries,
  // where A's Hessian is singular in every in-plane direction.
  AreaOutcome from_dirichlet_volume(double V0) {
    const CmcResult<Net> d = dirichlet_solution(o.H, &V0);
    if (!d.summary.converged) return {d.H, false, Status::NoConvergence, "no minimiser of D at V = " + num(V0)};
    p.base.P = d.net.points();
    double H = d.H;
    choose_rule();
    const std::string from = "from the minimiser of D at V = " + num(V0) + " (H = " + num(d.H) + ")";
    std::string note;
    const bool ok = homotopy(
        H,
        [&](double& h, double e) {
          p.eps = e;
          const CmcOptions so = stage_options(e);
          choose_rule_for(so.tolerance);
          theta = 1e-3;
          return bordered_correct(V0, h, e == 0.0 ? o.tolerance : so.tolerance).ok;
        },
        note, &V0);
    if (!ok) {
      p.eps = 0.0;
      return {H, false, Status::NoConvergence, note + " at fixed V " + from};
    }
    if (!note.empty()) note = " (" + note + ")";
    p.eps = 0.0;
    note += finish_volume(V0, H);
    return {H, true, Status::Converged, "the volume-constrained critical point of A " + from + note};
  }

  // The test before route 0 (docs/cmc.md, "The mean-curvature start"): the relative first
  // variation of A_H at the paper's D_H critical point at H (in the V form at the minimiser of D
  // at V0, with its multiplier H, which can only overstate it), by a rule chosen for
  // 0.1 × kConformalFirstVariation; +inf when that point does not exist. On conformal data that
  // point is already a critical point of A_H to within the degree (the conformal sphere triangle:
  // 8.2e-7, 3.6e-8, 1.6e-9, 6.5e-11 at n = 10, 12, 14, 16); from n = 12 on the routes below
  // converge from it in one iteration, where route 0's least squares cost up to 0.3 s (at n = 10
  // both end at the same numerical limit). On the Fig. 1 circle it is 7e-2. Leaves the net and the
  // rule as they were.
  double dirichlet_first_variation(const double* V0) {
    const CmcResult<Net> d = dirichlet_solution(o.H, V0);
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

  // Route 0 of both forms (docs/cmc.md, "The mean-curvature start"): the least-squares
  // mean-curvature surface (the functional "mean-curvature" by the same solver, from the D start
  // of dirichlet_solution; at H within kMeanCurvatureStartIterations, or in the V form at V0 with
  // its H), converged or not (where √Φ stops above its tolerance the surface is still far nearer a
  // critical point of A_H than the D_H critical point is), then at most kMeanCurvatureStartCorrector Newton iterations on A_H itself
  // (the bordered corrector at V0 in the V form), no regulariser, and where they stall the final
  // phases (finish; finish_volume in the V form). Kept when they meet the tolerance at a regular
  // net whose rule meets its own; otherwise the net, rule, damping, ε, H and the soft-mode verdict
  // go back to what they were, `note` says how it ended, and the caller goes on with its routes
  // from the D_H critical point. Measured on the circle (H = −0.5, −0.9, n = 8 … 16 where the least
  // squares converge): 2–5 iterations, and the critical point reached lies 4–80× nearer the sphere
  // than the one the routes from the D_H critical point reach (both with first variations below
  // 1e-11: A_H is nearly flat along its tangential valley, and Φ pins the geometry). From least
  // squares above their tolerance (2026-12-05): the circle at n = 6 and at H = −0.9, n = 8, the
  // helicoid at n = 4 and the tensor catenoid at n = 6 and 8 converge this way, the last three
  // where the routes from the D_H point stop at a numerical limit or take twice as long; the
  // tensor catenoid at n = 12 from √Φ 2.3e-6 after the H form's 300 iterations.
  bool from_mean_curvature(const double* V0, double& H, std::string& note, int& steps) {
    CmcOptions om = o;
    om.functional = CmcFunctionalKind::MeanCurvature;
    if (!V0) om.max_least_squares_iterations = std::min(o.max_least_squares_iterations, kMeanCurvatureStartIterations);
    const CmcResult<Net> m = solve_mean_curvature(data, om, &dirichlet_solution(o.H, V0));
    summary.iterations += m.summary.iterations;
    const std::string start = "the least-squares mean-curvature surface (√Φ = " + num(m.summary.residual, 3) +
                              (m.summary.converged                                      ? std::string()
                               : m.summary.residual > o.mean_curvature_tolerance ? ", above its tolerance"
                                                                                   : ", not converged") +
                              ")";
    if (!m.net.points().allFinite() || !std::isfinite(m.H)) {
      note = start + " is not finite";
      return false;
    }
    const State before = save();
    const double H0 = H;
    p.base.P = m.net.points();
    p.eps = 0.0;
    if (V0) H = m.H;
    bool rule_ok = choose_rule();
    theta = 1e-3;
    // At most kMeanCurvatureStartCorrector Newton iterations on A_H (V form: bordered, at V0).
    auto newton = [&] {
      if (V0) return bordered_correct(*V0, H, o.tolerance, kMeanCurvatureStartCorrector);
      CorrectorStats c;
      if (o.solver == CmcSolver::Ceres) {
        CmcOptions co = o;
        co.max_corrector_iterations = kMeanCurvatureStartCorrector;
        c = ceres_correct(p, H, co);
      } else {
        c = area_newton_correct(p, H, o, kMeanCurvatureStartCorrector, theta, 0.0);
      }
      summary.iterations += c.iterations;
      return c;
    };
    CorrectorStats st = newton();
    std::string finished;
    if (!st.ok && std::isfinite(st.residual)) {
      if (V0) {
        finished = finish_volume(*V0, H);
        st.residual = vresidual(*V0, H);
        st.ok = st.residual <= o.tolerance;
      } else {
        const CorrectorStats t = finish(H, o.max_corrector_iterations);
        summary.iterations += t.iterations;
        st.ok = t.ok;
        st.residual = t.residual;
        const std::string phases = final_phases(t, true);
        if (!phases.empty()) finished = " and " + phases;
      }
      // The rule in use now (the final phases choose it again where it missed its tolerance).
      rule_ok = rule_change <= 0.1 * o.tolerance;
      // The final phases can move the net far along the surface (the tensor catenoid at n = 6:
      // control points by up to 1.4): at a regular net reached the rule is checked again, refined
      // where it misses its tolerance there, and the Newton iterations run again with the finer
      // one. (Not at a degenerate net, which route 0 gives up anyway: there the rule would be
      // refined to its cap in vain, 0.9 s on the sphere patch at n = 8.)
      const auto is_regular = [&] {
        const Net reached = make_net(data, p.P());
        return regularity(reached, area(reached)).ok;
      };
      if (st.ok && rule_ok && is_regular()) {
        const std::shared_ptr<const AreaForm> a0 = p.a;
        rule_ok = refine_rule();
        if (rule_ok && !p.a->same_rule(*a0)) {
          const CorrectorStats again = newton();
          st.ok = again.ok;
          st.residual = again.residual;
          st.iterations += again.iterations;
          finished += " and again with a finer rule in " + std::to_string(again.iterations);
        }
      }
    }
    // Kept only where the routes below would not do better by the common end's tests: the rule
    // meets its tolerance at the net and the parametrisation is regular.
    const Net net = make_net(data, p.P());
    const bool regular = st.ok && regularity(net, area(net)).ok;
    if (st.ok && rule_ok && regular) {
      note = start + " corrected on A_H in " + std::to_string(st.iterations) + " iteration(s)" + finished;
      if (V0) steps = m.continuation_steps;
      return true;
    }
    if (!V0 && !st.ok && rule_ok && st.residual <= kAreaStallResidual && regularity(net, area(net)).ok)
      route0_end = RouteEnd{save(), start + " corrected on A_H in " + std::to_string(st.iterations) +
                                        " iteration(s)" + finished + ", to " + num(st.residual, 3)};
    note = start + (!st.ok ? " was corrected on A_H to " + num(st.residual, 3) + " only"
                    : !rule_ok ? " was corrected on A_H, but the area rule misses its tolerance there"
                               : " was corrected on A_H to a degenerate parametrisation");
    restore(before);
    H = H0;
    return false;
  }

  // The end of the V form at ε = 0 when its residual is above the tolerance. The V form's critical
  // point is the A_H critical point at its multiplier H: the H form's final phases at the H
  // reached, then bordered iterations back onto V = V0; kept when the V form's residual falls.
  // Returns "; finished by …" for the message when kept, else "".
  std::string finish_volume(double V0, double& H) {
    if (vresidual(V0, H) <= o.tolerance) return "";
    const Eigen::VectorXd y = p.get();
    const std::shared_ptr<const AreaForm> a0 = p.a;
    const double Hs = H, change0 = rule_change;
    double r0 = vresidual(V0, H);
    const CorrectorStats t = finish(H, 2 * o.max_corrector_iterations);
    summary.iterations += t.iterations;
    theta = 1e-8;
    bordered_correct(V0, H, o.tolerance, 8);
    if (p.a != a0) {
      // finish chose another rule: the start's residual on it, so that the two compare.
      const Eigen::VectorXd y1 = p.get();
      p.set(y);
      r0 = vresidual(V0, Hs);
      p.set(y1);
    }
    if (!(vresidual(V0, H) < r0)) {
      p.set(y);
      p.a = a0;
      rule_change = change0;
      H = Hs;
      return "";
    }
    const std::string phases = final_phases(t, false);
    return "; finished by " +
           (phases.empty() ? std::string("the bordered corrector") : phases + " at H and the bordered corrector");
  }

  // V mode, route 3 (the last; docs/cmc.md, V mode step 4; alone with "start": "minimal-surface"):
  // continuation in V from the critical point of A at H = 0 (V = V_min) to V0, as route 2 continues
  // from V1: the start and every step to max(tolerance, 1e-8) with fresh damping, then the bordered
  // corrector and the final phases at V0. Measured on the circle (H = −0.5 cap's V0): n = 6, 8, 10
  // converge in 10, 2 and 13 steps. With every step to the tolerance itself and the damping carried
  // over from the start (the first version) the first step stalled at 5e-10 above 1e-11 and the
  // steps below it found no point: "beyond V ≈ 1e-4" at n = 6 and 8.
  AreaOutcome volume_continuation(const Eigen::MatrixX3d& start, int& steps) {
    p.base.P = start;
    const double step_tol = std::max(o.tolerance, kContinuationStepTolerance);
    if (!minimal_surface(step_tol))
      return {0.0, false, Status::NoConvergence, "no critical point of the area (H = 0) from the Dirichlet extremal"};
    const double Vmin = p.base.f->volume_form().value(p.P());
    AreaOutcome out = continue_volume(Vmin, 0.0, *o.V, steps, step_tol, true);
    if (!out.ok) return out;
    double H = out.H;
    choose_rule();
    theta = 1e-3;
    bordered_correct(*o.V, H);
    const std::string note = finish_volume(*o.V, H);
    return {H, true, Status::Converged,
            "V continued from the minimal surface (V = " + num(Vmin) + ") in " + std::to_string(steps) + " step(s)" +
                note};
  }

  // Continuation in V along the volume-constrained critical points of A, from the one in p (volume
  // Vs, multiplier H) to V0: the Euler predictor along the tangent per unit V (K dY + 2∇V dH = 0,
  // ∇V·dY = 1; K regularised by 1e-8 C), the bordered corrector to `step_tol` at each step, and the
  // step control of the H continuation (StepController over V − Vs). A corrected point is on the
  // branch when it lies closer to the prediction than half its distance to the last point, both
  // measured along the surface normals (normal_gap): the corrector moves the points along the
  // surface too, in the nearly singular tangential modes, by as much as the step itself (measured
  // on the circle past the hemisphere: the point test of the H continuation, on_branch, then
  // rejected every step from V = 1.81 on).
  AreaOutcome continue_volume(double Vs, double H, double V0, int& steps, double step_tol, bool fresh_damping) {
    auto tangent = [&](double h, Eigen::VectorXd& dY, double& dH) {
      const SymFactor fac(p.hessian(h) + 1e-8 * p.C);
      const Eigen::VectorXd gV = p.volume_gradient(), b = fac.solve(gV);
      const double s = gV.dot(b);
      if (!(std::abs(s) > 0) || !b.allFinite()) return false;
      dY = b / s;
      dH = -1.0 / (2.0 * s);
      return true;
    };
    Eigen::VectorXd dY;
    double dH = 0;
    if (!tangent(H, dY, dH))
      return {H, false, Status::NoConvergence, "the volume has no gradient at the start of the volume continuation"};
    Eigen::VectorXd y = p.get();
    Net last = make_net(data, p.P());
    const double target = V0 - Vs;
    StepController control(target, target, o);
    std::string rejected;  // why the last step was rejected, for the message
    while (!control.reached_target()) {
      if (!control.attempt())
        return {H, false, Status::NoConvergence,
                "volume continuation stopped at V ≈ " + num(Vs + control.h()) + " after max_continuation_steps"};
      const StepController::Step step = control.propose();
      p.set(y + dY * step.s);
      const Net pred = make_net(data, p.P());
      double Hn = H + dH * step.s;
      if (fresh_damping) theta = 1e-3;
      const CorrectorStats st = bordered_correct(Vs + step.hn, Hn, step_tol);
      const Net now = make_net(data, p.P());
      const double dev = normal_gap(pred, now), move = normal_gap(last, now);
      const bool near_prediction = st.ok && std::isfinite(move) && dev <= 0.5 * move + 1e-12 * std::max(1.0, y.norm());
      rejected = !st.ok ? "its corrector stopped at a relative residual of " + num(st.residual, 3)
                 : !near_prediction ? "the corrected surface left the branch"
                                    : "the volume has no gradient there";
      if (near_prediction && tangent(Hn, dY, dH)) {
        y = p.get();
        last = now;
        H = Hn;
        ++steps;
        control.accept(step, st.iterations);
      } else {
        p.set(y);  // dY, dH are still the tangent at y (tangent() writes only when it succeeds)
        if (!control.reject(step))
          return {H, false, Status::NoConvergence,
                  "no volume-constrained critical point of the area beyond V ≈ " + num(Vs + control.h()) +
                      " (at the last step tried, " + rejected + ")"};
      }
    }
    return {H, true, Status::Converged,
            "V continued from V = " + num(Vs) + " in " + std::to_string(steps) + " step(s)"};
  }

  // V mode, route 2 (docs/cmc.md, V mode step 3): route 1 at V1 = Vref + (V0 − Vref)/k for
  // k = 16, 64, 256 (Vref the volume of the Dirichlet extremal, so V1 lies between the nearly
  // minimal surface and V0 wherever the origin is: V changes by a constant with the origin, the
  // same for every surface with this boundary), the first whose start meets 1e-8 (relative; the
  // tolerance if looser) and from which the continuation reaches V0, each step corrected to the
  // same (the crawl below it is left to the end), then the bordered corrector at V0 and the V
  // form's end (finish_volume).
  // Measured on the circle past the hemisphere (docs/cmc.md, "Past the hemisphere: continuation
  // in V"): the larger caps, whose D minimiser keeps the regulariser above ε = 0.018 (H = −0.7).
  // k = 4 first cost 7 s more at n = 10, H = −0.7, where route 1 fails at V1 = 2.88, and at n = 12
  // it ends there at 9.2e-7, too far for a start.
  AreaOutcome volume_continuation_from_smaller(double V0, double Vref, int& steps) {
    std::string tried;
    for (const double k : {16.0, 64.0, 256.0}) {
      const double V1 = Vref + (V0 - Vref) / k;
      if (!(V1 != V0)) break;
      const double step_tol = std::max(o.tolerance, kContinuationStepTolerance);
      const AreaOutcome start = from_dirichlet_volume(V1);
      // Route 1 may end "ok" above the tolerance (a numerical limit); a start for the
      // continuation must meet the steps' tolerance.
      const double r1 = start.ok ? vresidual(V1, start.H) : std::numeric_limits<double>::infinity();
      if (!(r1 <= step_tol)) {
        tried += (tried.empty() ? "" : "; ") + num(V1) + ": " +
                 (start.ok ? "route 1 ended at " + num(r1) : start.message);
        continue;
      }
      steps = 0;
      const AreaOutcome out = continue_volume(V1, start.H, V0, steps, step_tol, true);
      if (!out.ok) {
        tried += (tried.empty() ? "" : "; ") + num(V1) + ": " + out.message;
        continue;
      }
      double H = out.H;
      choose_rule();
      theta = 1e-3;
      bordered_correct(V0, H);
      const std::string note = finish_volume(V0, H);
      return {H, true, Status::Converged,
              "the volume-constrained critical point of A continued in V from V1 = " + num(V1) + " (H = " +
                  num(start.H) + ", from the minimiser of D there) in " + std::to_string(steps) + " step(s)" + note};
    }
    steps = 0;
    return {0.0, false, Status::NoConvergence,
            "no continuation in V from smaller volumes (V1 = " + (tried.empty() ? std::string("none") : tried) + ")"};
  }
};

template <class Net>
CmcResult<Net> solve_area_impl(const Net& data, const CmcOptions& o) {
  // The Hessian's per-thread scratch lives as long as the solve (AreaForm::hessian).
  struct ReleaseScratch {
    ~ReleaseScratch() { AreaForm::release_scratch(); }
  } release_scratch;
  CmcResult<Net> res;
  res.functional = CmcFunctionalKind::Area;
  {
    ScopedTimer timer(res.summary.seconds);
    DirichletStart start = dirichlet_start(data, o);
    CmcProblem& base = start.p;
    const std::vector<int>& fixed_idx = start.fixed_idx;
    const Eigen::MatrixX3d extremal = base.P;
    const Eigen::MatrixXd Cff = base.f->gram()(base.free, base.free);
    AreaSolve<Net> s{data,
                     o,
                     AreaProblem{base, nullptr, kron(Cff, Eigen::Matrix3d::Identity())},
                     is_triangular(data),
                     data.n(),
                     is_triangular(data) ? data.n() : static_cast<int>(0),
                     1.0,
                     res.summary};
    if (o.progress) s.p.progress = &o.progress;
    if constexpr (std::is_same_v<Net, TensorNet>) s.m = data.m();
    if constexpr (std::is_same_v<Net, TriangularNet>) s.m = data.n();
    AreaOutcome out;
    // Route 0: from the least-squares mean-curvature surface (AreaSolve::from_mean_curvature).
    std::string start_note;
    double h0 = o.H;
    // Not on data where the D_H critical point already nearly is a critical point of A_H
    // (conformal data): its first variation at most kConformalFirstVariation.
    const bool mc_start = o.area_start == AreaStart::MeanCurvature;
    const bool minimal_start = o.area_start == AreaStart::MinimalSurface;
    const double r_dirichlet = mc_start ? s.dirichlet_first_variation(o.V ? &*o.V : nullptr) : 0.0;
    const bool tried_mc = mc_start && r_dirichlet > kConformalFirstVariation;
    const bool from_mc =
        tried_mc && s.from_mean_curvature(o.V ? &*o.V : nullptr, h0, start_note, res.continuation_steps);
    if (from_mc) {
      out = {h0, true, Status::Converged,
             (o.V ? "the volume-constrained critical point of A from " : "the critical point of A_H from ") +
                 start_note};
    } else if (minimal_start && o.V) {
      // "start": "minimal-surface": the branch from the critical point of A at H = 0 alone.
      out = s.volume_continuation(extremal, res.continuation_steps);
    } else if (minimal_start && o.H != 0.0) {
      out = s.continuation(extremal, fixed_idx, res.continuation_steps);
    } else if (o.V) {
      const double Vref = base.f->volume_form().value(extremal);
      // Each candidate's residual on a checked rule (AreaSolve::checked_residual), so that the two
      // are compared to within 0.1 × the tolerance; the final rule check refines and corrects again.
      out = s.from_dirichlet_volume(*o.V);
      const double r1 = out.ok ? s.checked_residual(out.H) : 0.0;
      if (out.ok && r1 > o.tolerance) {
        // Route 1 ended above the tolerance (a numerical limit): route 2 too, and the lower
        // residual is kept (measured: docs/cmc.md, "Past the hemisphere: continuation in V").
        const auto route1_end = s.save();
        const AreaOutcome route1 = out;
        int steps = 0;
        out = s.volume_continuation_from_smaller(*o.V, Vref, steps);
        const double r2 = out.ok ? s.checked_residual(out.H) : std::numeric_limits<double>::infinity();
        if (r2 < r1) {
          res.continuation_steps = steps;
        } else {
          const std::string why = out.ok ? "ended at " + num(r2) : "failed: " + out.message;
          s.restore(route1_end);
          out = route1;
          out.message += "; kept, as the continuation in V from smaller volumes " + why;
        }
      } else if (!out.ok) {
        const AreaOutcome route1 = out;
        out = s.volume_continuation_from_smaller(*o.V, Vref, res.continuation_steps);
        if (!out.ok) {
          const AreaOutcome route2 = out;
          s.theta = 1.0;  // route 3 as it was, not with the other routes' damping or regulariser
          s.p.eps = 0.0;
          res.continuation_steps = 0;
          out = s.volume_continuation(extremal, res.continuation_steps);
          if (!out.ok)
            out.message += " (and from the minimiser of D at V0: " + route1.message + "; " + route2.message + ")";
        }
      }
    } else if (o.H == 0.0) {
      s.p.base.P = extremal;
      out.ok = s.minimal_surface(o.tolerance);
      out.message = "critical point of the area (H = 0) from the Dirichlet extremal";
      if (!out.ok) {
        // The corrector stopped above the tolerance. Where it got within kAreaStallResidual of a
        // critical point it stalled in the soft tangential modes, as the H ≠ 0 route's last stages
        // do (docs/cmc.md, "Not done yet"): that is a numerical limit, reported with the first
        // variation reached by the checks below; further off there is no critical point near
        // the extremal.
        const double r = s.p.residual_at(0.0, 0.0);
        out.ok = std::isfinite(r) && r <= kAreaStallResidual;
        out.message = out.ok ? "the corrector from the Dirichlet extremal (H = 0) stalled at " + num(r)
                             : "no critical point of the area (H = 0) from the Dirichlet extremal (the corrector "
                               "stopped at a relative first variation of " + num(r) + ")";
      }
    } else {
      std::string note;
      if (s.from_dirichlet(o.H, note)) {
        out = {o.H, true, Status::Converged,
               "the D_H critical point at H = " + num(o.H) + " corrected on A_H" +
                   (note.empty() ? "" : " (" + note + ")")};
        // Ended above the tolerance (a numerical limit): route 2 too, kept only where it meets the
        // tolerance (on a checked rule). Measured on the tensor catenoid piece at H = −0.8: n = 6,
        // route 1 stops at 1.7e-8, route 2 converges in one step; n = 8, route 2 ends lower than
        // route 1 (6.9e-11 against 1.3e-10) but its mean curvature is 4× further from H (−1.04 …
        // −0.71 against −0.83 … −0.74 at corner margin 0.1), so a lower numerical limit is not kept
        // (docs/cmc.md, "The minimal-surface start").
        const double r1 = s.checked_residual(o.H);
        if (r1 > o.tolerance) {
          const auto route1_end = s.save();
          int steps = 0;
          const AreaOutcome route2 = s.continuation(extremal, fixed_idx, steps);
          const double r2 = route2.ok ? s.checked_residual(o.H) : std::numeric_limits<double>::infinity();
          if (r2 <= o.tolerance) {
            res.continuation_steps = steps;
            out = route2;
            out.message += " (kept: the D_H critical point corrected on A_H ended at " + num(r1, 3) + ")";
          } else {
            s.restore(route1_end);
            out.message += "; kept, as the continuation from H = 0 " +
                           (route2.ok ? "ended above the tolerance too, at " + num(r2, 3) : "failed: " + route2.message);
          }
        }
      } else {
        out = s.continuation(extremal, fixed_idx, res.continuation_steps);
        if (out.ok) out.message += " (" + note + ")";
      }
    }
    std::string why;
    if (!o.V && tried_mc && !from_mc && s.keep_route0_end(out, why)) {
      // Route 0's end is lower than theirs: reported (a numerical limit by the checks below).
      out = {o.H, true, Status::Converged, "the end of route 0, " + s.route0_end->note + " (kept: " + why + ")"};
    } else if (tried_mc && !from_mc) {
      out.message += " (route 0: " + start_note + ")";
    }
    if (mc_start && !tried_mc)
      out.message += " (route 0 not tried: the first variation of A_H at the " +
                     std::string(o.V ? "minimiser of D at V0" : "D_H critical point") + " is " + num(r_dirichlet, 3) +
                     ", at most " + num(kConformalFirstVariation, 1) + ", as on conformal data)";
    if (!o.V) out.H = out.ok ? o.H : out.H;
    // The final rule check: refine while the rule's measured error (against a finer rule, also at
    // the cap) is above its tolerance at the final net, and correct again with the finer rule. A
    // rule that still misses its tolerance is reported (NumericalLimit): the first variation is
    // then only known to within that error.
    if (out.ok) {
      s.choose_rules_again = false;  // refined only, never chosen from the start again
      for (int round = 0; round < 4; ++round) {
        const std::shared_ptr<const AreaForm> a0 = s.p.a;
        const bool rule_ok = s.refine_rule();
        if (s.p.a->same_rule(*a0)) {
          if (!rule_ok)
            out = {out.H, false, Status::NumericalLimit,
                   "the area quadrature does not reach its error tolerance " + num(0.1 * o.tolerance) +
                       ": measured error " + num(s.rule_change) + " with " +
                       std::to_string(a0->points_per_direction()) + " points per direction" +
                       (a0->levels() > 0   ? " on " + std::to_string(a0->levels() + 1) + " geometric pieces"
                        : a0->grading() > 1 ? " (graded)"
                                            : "") +
                       " (a folded or nearly singular parametrisation at a corner); reached after: " + out.message};
          break;
        }
        const CorrectorStats st = o.V ? s.bordered_correct(*o.V, out.H) : s.correct(out.H, o.tolerance);
        if (!st.ok) {
          out = {out.H, false, Status::NumericalLimit,
                 "the correction with the refined quadrature rule (q = " +
                     std::to_string(s.p.a->points_per_direction()) + ") stopped at a relative first variation of " +
                     num(st.residual) + s.soft_verdict(st.residual, false) + "; reached after: " + out.message};
          break;
        }
      }
    }
    const Net net = make_net(data, s.p.P());
    res.net = net;
    res.H = out.H;
    res.D = base.f->dirichlet(s.p.P());
    res.V = base.f->volume(s.p.P());
    res.DH = res.D + 2.0 * out.H * res.V;
    res.A = s.p.area();
    res.energy = res.A + 2.0 * out.H * res.V;
    res.quadrature_points = s.p.a->points_per_direction();
    res.quadrature_grading = s.p.a->grading();
    res.quadrature_levels = s.p.a->levels();
    res.quadrature_nodes = s.p.a->nodes();
    res.summary.residual = s.p.residual(out.H);
    if (o.V) {
      const VolumeForm& vf = base.f->volume_form();
      const double vs = vf.value_scale(s.p.P());
      res.summary.residual = std::max(res.summary.residual, std::abs(res.V - *o.V) / (vs > 0 ? vs : 1.0));
    }
    const Regularity reg = final_regularity(net, res.A);
    if (out.ok && !(res.summary.residual <= o.tolerance)) {
      out = {out.H, false, Status::NumericalLimit,
             "the final net misses the first variation of A_H by " + num(res.summary.residual) + " (relative)" +
                 s.soft_verdict(res.summary.residual, true) + "; reached after: " + out.message};
    }
    if (!reg.ok) {
      out.ok = false;
      out.why = Status::NoConvergence;
      out.message = "degenerate parametrisation: " + reg.describe() + " (not a CMC surface); " + out.message;
    }
    if (out.ok) {
      res.summary.message = out.message;
      res.summary.set_converged();
    } else {
      res.summary.set_failed(out.why, out.message);
    }
  }
  report(o.progress, "cmc area", 1, 1);
  return res;
}

}  // namespace

CmcResult<TriangularNet> solve_area(const TriangularNet& data, const CmcOptions& options) {
  return solve_area_impl(data, options);
}
CmcResult<TensorNet> solve_area(const TensorNet& data, const CmcOptions& options) {
  return solve_area_impl(data, options);
}

}  // namespace bpde::cmc_detail
