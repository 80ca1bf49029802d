// The A_H problem's evaluations and its two Newton correctors (area_problem.h): the regularised
// Newton corrector on F_ε and the truncated Newton phase on A_H, which ends in the soft-mode phase.
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/area/tuning.h"

namespace bpde::cmc_detail {
using namespace area_impl;  // the tuning constants
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
  if (sparse) return Eigen::MatrixXd(hessian_sparse(H));
  Eigen::MatrixXd K = a->hessian(base.P, base.free);
  if (eps != 0.0) K = (1.0 - eps) * K + eps * C;
  if (H != 0.0) K += 2.0 * H * base.f->volume_form().hessian(base.P, base.free);
  return K;
}

Eigen::SparseMatrix<double> AreaProblem::hessian_sparse(double H) const {
  Eigen::SparseMatrix<double> K = sparse->area_hessian(*a, base.P);
  if (eps != 0.0) {
    K *= 1.0 - eps;
    K = sparse->add(K, eps, sparse->C);
  }
  if (H != 0.0) K = sparse->add(K, 2.0 * H, sparse->volume_hessian(base.P));
  return K;
}

double AreaProblem::residual_at(double H, double e, Eigen::VectorXd* g) const {
  if (progress) report(*progress, progress_stage, progress_done, 1);
  Eigen::MatrixX3d G, S;
  a->gradient_rows_and_scale(base.P, base.free, &G, &S);
  if (e != 0.0) {
    Eigen::MatrixX3d GD(G.rows(), 3), SD(G.rows(), 3);
    if (sparse) {  // the Gram's free rows, kept (sparse_terms.h)
      for (int c = 0; c < 3; ++c) {
        GD.col(c) = sparse->Cfa * base.P.col(c);
        SD.col(c) = sparse->Cfa_abs * base.P.col(c).cwiseAbs();
      }
    } else {
      const Eigen::MatrixXd Cf = base.f->gram()(base.free, Eigen::all);
      for (int c = 0; c < 3; ++c) {
        GD.col(c) = Cf * base.P.col(c);
        SD.col(c) = Cf.cwiseAbs() * base.P.col(c).cwiseAbs();
      }
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

namespace {

// One regularised Newton trial of area_newton_correct from y (gradient g, value f): the step of
// (K + μC) δ = −g with chord corrections by the same factor (at most kNewtonChords, while the
// residual falls: they bring a long step in the soft, tangential directions back to the floor of
// the curved valley), judged by the gain ratio ρ of A_H, or where the predicted change is rounding
// noise (kValueNoise) by the fall of the Euclidean norm of the gradient alone (a short step along
// −(K + μC)⁻¹ g always lowers it when K is positive semidefinite, the max-norm residual not
// necessarily). The surface must stay regular at the nodes. p is at the trial point when it is
// accepted, at y otherwise.
struct NewtonTrial {
  bool accepted = false;
  bool on_gradient_alone = false;  ///< accepted on the gradient's fall, not on ρ: θ stays
  double rho = 0.0, f = 0.0, residual = 0.0;
  Eigen::VectorXd g;
};

// The factor of K + μC: dense Cholesky for one patch, sparse (sparse_terms.h) for a complex.
struct DenseTrialFactor {
  Eigen::LLT<Eigen::MatrixXd> llt;
  bool compute(const Eigen::MatrixXd& K, const AreaProblem& p, double mu) {
    llt.compute(K + mu * p.C);
    return llt.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return llt.solve(b); }
};
struct SparseTrialFactor {
  SparseSymFactor& f;  // kept by the corrector: one symbolic analysis for all its factorisations
  bool compute(const Eigen::SparseMatrix<double>& K, const AreaProblem& p, double mu) {
    return f.refactor(p.sparse->add(K, mu, p.sparse_C()));
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return f.solve(b); }
};

template <class Mat, class Factor>
NewtonTrial newton_trial(AreaProblem& p, double H, const Mat& K, Factor llt, const Eigen::VectorXd& y,
                         const Eigen::VectorXd& g, double f, double mu, double fscale, double accept_ratio) {
  NewtonTrial t;
  if (!llt.compute(K, p, mu)) return t;
  Eigen::VectorXd d = -llt.solve(g);
  if (!d.allFinite()) return t;
  p.set(y + d);
  Eigen::VectorXd gn;
  double rn = p.residual(H, &gn);
  for (int c = 0; c < kNewtonChords && std::isfinite(rn); ++c) {
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
  const double pred = g.dot(d) + 0.5 * d.dot(Eigen::VectorXd(K * d));
  const double fn = p.value(H);
  if (std::isfinite(fn) && std::isfinite(rn) && p.a->min_normal(p.P()) > 0.0) {
    const bool falls = gn.norm() < g.norm();
    t.rho = std::abs(pred) > kValueNoise * fscale ? (fn - f) / pred : 0.0;
    t.on_gradient_alone = falls && !(t.rho > accept_ratio);
    t.accepted = falls || t.rho > accept_ratio;
  }
  if (!t.accepted) {
    p.set(y);
    return t;
  }
  t.f = fn;
  t.residual = rn;
  t.g = std::move(gn);
  return t;
}

}  // namespace

CorrectorStats area_newton_correct(AreaProblem& p, double H, const CmcOptions& o, int max_iterations, double& theta,
                                   double target) {
  // Levenberg–Marquardt on A_H: (K + μC) δ = -g, μ = θ r (r the relative residual, C the Dirichlet
  // Gram), each step a newton_trial; θ follows the trials (kNewtonDamping, solvers/optim/damping.h).
  const optim::Damping& damping = kNewtonDamping;
  CorrectorStats st;
  Eigen::VectorXd g;
  st.residual = p.residual(H, &g);
  double f = p.value(H);
  const double fscale = std::abs(p.area()) + 2.0 * std::abs(H) * std::abs(p.base.f->volume(p.P())) + 1e-300;
  int stalled = 0;
  std::vector<double> history{st.residual};
  double best_residual = st.residual;  // the lowest residual met and its point
  Eigen::VectorXd best_y = p.get();
  SparseSymFactor factor;  // complexes (sparse_terms.h)
  for (int it = 0;; ++it) {
    if (!std::isfinite(st.residual)) return st;
    if (st.residual <= o.tolerance || (target > 0 && p.eps != 0.0 && p.residual_at(H, 0.0) <= target)) {
      st.ok = true;
      return st;
    }
    if (it >= max_iterations || stalled >= kNewtonStallIterations) return st;
    // An ε-stage in the heavily damped regime crawling along the valley (kCrawlDamping): stop and
    // let the homotopy change ε instead.
    if (p.eps != 0.0 && theta >= kCrawlDamping && history.size() > kCrawlWindow &&
        st.residual > 0.5 * history[history.size() - 1 - kCrawlWindow])
      return st;
    // At ε = 0 on a complex small enough for the final phases (kDenseFinalPhasesLimit): a
    // corrector whose lowest residual of the last kCrawlWindow + 1 iterations is not half the
    // lowest before wanders along the tangential valley (the ring of 4 tensor patches of the
    // catenoid at n = 5 and 6 went on between 1e-7 and 1e-6 for 40 iterations, then crawled at
    // θ ≈ 2e4, up to the 60 iterations allowed); it stops at the lowest point it met and leaves the
    // rest to the final phases. Single patches keep their path (measured and tested on it).
    const bool final_phases_follow = p.base.f->assembly() && !(p.sparse && 3 * p.k() > kDenseFinalPhasesLimit);
    if (p.eps == 0.0 && final_phases_follow && history.size() > kCrawlWindow + 1) {
      const auto recent = history.end() - (kCrawlWindow + 1);
      if (*std::min_element(recent, history.end()) > 0.5 * *std::min_element(history.begin(), recent)) {
        if (best_residual < st.residual) {
          p.set(best_y);
          st.residual = best_residual;
        }
        return st;
      }
    }
    Eigen::MatrixXd K;
    Eigen::SparseMatrix<double> Ks;
    if (p.sparse) {  // a complex: the sparse Hessian and factor (sparse_terms.h)
      Ks = p.hessian_sparse(H);
      if (!Eigen::Map<const Eigen::VectorXd>(Ks.valuePtr(), Ks.nonZeros()).allFinite()) return st;
    } else {
      K = p.hessian(H);
      if (!K.allFinite()) return st;
    }
    const Eigen::VectorXd y = p.get();
    bool accepted = false;
    for (int tries = 0; tries < damping.max_tries && !accepted; ++tries) {
      const double mu = theta * st.residual;
      NewtonTrial t = p.sparse ? newton_trial(p, H, Ks, SparseTrialFactor{factor}, y, g, f, mu, fscale, damping.accept_ratio)
                               : newton_trial(p, H, K, DenseTrialFactor{}, y, g, f, mu, fscale, damping.accept_ratio);
      if (!t.accepted) {
        damping.rejected(theta);
        continue;
      }
      accepted = true;
      stalled = t.residual < st.residual || t.on_gradient_alone ? 0 : stalled + 1;
      f = t.f;
      g = std::move(t.g);
      st.residual = t.residual;
      if (!t.on_gradient_alone) damping.accepted(theta, t.rho);
    }
    ++st.iterations;
    if (accepted && st.residual < best_residual) {
      best_residual = st.residual;
      best_y = p.get();
    }
    history.push_back(st.residual);
    if (!accepted) return st;
  }
}

namespace {

// The best point of one truncated Newton iteration from y (gradient g, residual r): the smallest
// Euclidean norm of the gradient (the max-norm residual can stall while it falls) over the cuts
// and the fractions of the dropped step. best.y empty: no trial lowered it.
struct TruncatedTrial {
  double norm, residual;
  Eigen::VectorXd y, g;
};

TruncatedTrial best_truncated_step(AreaProblem& p, double H, const Eigen::VectorXd& g, double r,
                                   const Eigen::VectorXd& lam, const Eigen::MatrixXd& Vm) {
  const double lmax = lam.cwiseAbs().maxCoeff();
  const Eigen::VectorXd c = Vm.transpose() * g;
  const Eigen::VectorXd y = p.get();
  TruncatedTrial best{g.norm(), r, {}, {}};
  for (double cut = kTruncationFirstCut; cut >= kTruncationLastCut; cut *= 0.1) {
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
    // The dropped (soft) modes by a fraction t of their Newton step, each trial followed by chord
    // corrections in the kept modes (at most kTruncatedChords), which bring it back to the floor
    // of the curved valley.
    for (double t : kSoftStepFractions) {
      Eigen::VectorXd d = kept + t * dropped;
      double prev = std::numeric_limits<double>::infinity();
      int rises = 0;
      for (int chord = 0; chord <= kTruncatedChords; ++chord) {
        p.set(y + d);
        Eigen::VectorXd gn;
        // Not finite also where |x_u ∧ x_v| vanishes at a node (n̂ = N/|N|): such a trial is out.
        const double rn = p.residual(H, &gn);
        if (!std::isfinite(rn)) break;
        // The second chord correction that does not lower ‖g‖ ends the trial: past that the
        // corrections diverge in the soft modes.
        if (gn.norm() >= prev && ++rises >= kTruncatedChordRises) break;
        prev = gn.norm();
        if (gn.norm() < best.norm) best = {gn.norm(), rn, p.get(), gn};
        const Eigen::VectorXd cn = Vm.transpose() * gn;
        for (Eigen::Index i : keep) d -= (cn(i) / lam(i)) * Vm.col(i);
      }
    }
  }
  return best;
}

// What the truncated phase leaves is in the soft modes: the soft-mode phase (soft_mode_phase.cpp)
// eliminates the hard ones and solves the reduced system; its counts go into st.
void soft_mode_phase_after(AreaProblem& p, double H, const CmcOptions& o, CorrectorStats& st) {
  const CorrectorStats soft =
      area_soft_mode_phase(p, H, o, kSoftModeIterationsPerCorrector * o.max_corrector_iterations);
  st.iterations += soft.iterations;
  st.soft_iterations = soft.iterations;
  st.trust_region_iterations = soft.trust_region_iterations;
  st.residual = soft.residual;
  st.ok = soft.ok;
  st.soft_stationary = soft.soft_stationary;
  st.trust_region_blocked = soft.trust_region_blocked;
}

}  // namespace

CorrectorStats area_truncated_newton(AreaProblem& p, double H, const CmcOptions& o, int max_iterations) {
  // Newton on A_H (ε = 0) restricted to the well-conditioned part of the Hessian. K v = λ C v (C the
  // Dirichlet Gram, so the cut does not depend on how the free points are scaled), v_iᵀ C v_j = δ_ij;
  // the kept step is -Σ_{|λ_i| > c λ_max} (v_iᵀ g / λ_i) v_i (the least-C-norm Newton step in the span
  // of the kept modes), the dropped step the same sum over the soft (tangential) modes. Each
  // iteration tries the cuts and fractions of best_truncated_step and keeps the best trial; it
  // stops when none lowers ‖g‖. Measured (docs/cmc_measurements.md): the normal part goes in one or
  // two steps, the soft part linearly (a few % to ~10 % a step).
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
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, p.dense_C());
    if (es.info() != Eigen::Success) break;
    const double lmax = es.eigenvalues().cwiseAbs().maxCoeff();
    if (!(lmax > 0) || !std::isfinite(lmax)) break;
    const Eigen::VectorXd y = p.get();
    TruncatedTrial best = best_truncated_step(p, H, g, st.residual, es.eigenvalues(), es.eigenvectors());
    ++st.iterations;
    if (best.y.size() == 0) {
      p.set(y);
      break;
    }
    p.set(best.y);
    g = std::move(best.g);
    st.residual = best.residual;
  }
  if (std::isfinite(st.residual) && st.residual > o.tolerance) refresh();
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  if (!st.ok && std::isfinite(st.residual)) soft_mode_phase_after(p, H, o, st);
  p.eps = e0;
  return st;
}


}  // namespace bpde::cmc_detail
