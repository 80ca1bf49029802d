// The soft-mode phase of the area functional (area_problem.h, area_soft_mode_phase;
// docs/cmc_algorithm.md, "The final phases").
//
// The method. At the point y0 where the truncated Newton phase stops, split the free coordinates
// by the generalised eigenproblem K v = λ C v (K the Hessian of A_H, C the Dirichlet Gram over the
// free points ⊗ Id_3, eigenvectors C-orthonormal): the soft modes Vs (|λ| < 1e-4 max|λ|: the
// nearly tangential, reparametrisation-like directions) and the hard modes Vh. Write
// y = y0 + Vs s + Vh h. For each s the hard equations Vhᵀ∇A_H(y) = 0 are well conditioned (their
// Hessian Vhᵀ K Vh has eigenvalues ≥ 1e-4 max|λ|) and are solved for h(s) by chord Newton steps
// (the factor of Vhᵀ K Vh from the last accepted point); what is left is the reduced first
// variation G(s) = Vsᵀ∇A_H(y0 + Vs s + Vh h(s)), whose Jacobian is the Schur complement
// J = Kss − Ksh Khh⁻¹ Khs (K in the split basis, at the point). The phase minimises ‖G‖² over s:
//  - solver newton: the library's Levenberg–Marquardt loop (levenberg_marquardt.h) with geodesic
//    acceleration and Levenberg's scaling (D = max diag JᵀJ · Id: s is in C-orthonormal
//    coordinates, so the damping is a trust region in the C-norm, as the corrector's μC);
//  - solver ceres: ceres::Solve on one residual block (G, with J as its Jacobian, both divided by
//    the largest column norm of J at the split point, from the split itself), Levenberg–Marquardt with the same scaling
//    (no Jacobi scaling, diag JᵀJ clamped to 1 from above and below: D = Id), and the same
//    stopping tests in an IterationCallback. The ceres route has no truncated Newton phase; this
//    phase follows its last corrector directly.
//
// Why. Measured at the end of stalled solves (docs/cmc_algorithm.md, "The final phases"): J has singular
// values down to 6e-12 (its largest 1.5e-4 on the tensor catenoid at n = 6), so the Newton step in
// the soft modes is long (|d|_C = 2.6 there), while G(s) is quadratic in s on a far smaller scale: with the
// hard modes eliminated exactly, ‖G‖ along the Newton direction rises from 1e-3 of the step on.
// The whole-space methods (the corrector, the truncated phase) do not separate the two scales. On
// the reduced system the loop moves s by up to 0.08 (C-norm; probe) and takes the Fig. 1 circle at
// H = −0.9 from 1.7e-10 (n = 8) and 5.9e-11 (n = 10) to below the tolerance 1e-11.
//
// It stops at the tolerance (max-norm relative residual, the solve's measure), after
// max_iterations, when ‖G‖ falls by less than 10 % in 100 iterations, or when no step lowers ‖G‖
// (30 trials with growing damping: LsStop::NoStep; with Ceres, its own convergence tests). In the
// last case the point is called stationary (soft_stationary; final_phases.cpp words the message) only
// when ‖JᵀG‖ <= 1e-3 ‖J‖_F ‖G‖ there: G lies along the nearly null directions of the reduced
// Hessian, a stationary point of ‖G‖ that is not a critical point of A_H. An evaluation that fails
// (a non-finite residual, h(s) not solved) restores h and the hard factor of the last good one.
// The phase starts only within a relative first variation of 1e-6. It leaves p at the point with
// the smallest residual it met.
//
// The trust-region part (CmcOptions::area_trust_region, default true; docs/cmc_algorithm.md, "The final phases"). Where the loop above stops above the
// tolerance, the system is split again at the best point and A_H itself is minimised along the
// valley floor: φ(s) = A_H(y0 + Vs s + Vh h(s)) has the gradient G(s) (the hard part of ∇A_H
// vanishes on the floor) and the Hessian J, so trust-region Newton on φ needs nothing new but a
// merit function. A_H's values cannot be it: along the soft modes they change by ‖G‖‖ds‖ ≈ 1e-11 ×
// 1e-3, far below their rounding (1e-16 of the sum of the terms over thousands of nodes), which is
// why every phase before judged its steps by ‖G‖, whose stationary points that are not critical
// points are where they stopped. The change of φ along a step is instead measured by Simpson's
// rule on G, ∫₀¹ G(s + τ ds)·ds dτ (trust_region_model.h), accurate to the rounding of G, which is
// relative to its terms. A descent method on φ does not see the stationary points of ‖G‖; it finds
// minima of A_H, so a critical point that is a saddle in the soft modes is left to the loop above.
// Measured (docs/cmc_measurements.md): of the H-form cases that ended `numerical-limit` there, all but the
// sphere triangle at n = 8 converge (in the first version: the tensor catenoid at n = 10 in 22
// trust-region steps, curve A at n = 10 in 74). Where the reduced Hessian turns positive definite
// the last steps are Newton steps inside the region (traced in the first version: the helicoid
// piece at n = 4, one, from 6.8e-11 to 6.7e-12; the catenoid boundary at n = 8, H = 0.12, five,
// of lengths 1.8e-2 … 5.3e-4, to 1.4e-12); elsewhere the first variation falls below the
// tolerance on the way down the valley (the tensor catenoid at n = 10, the lowest eigenvalue still
// −1.1e-6 of the largest at the last step). The V form gains through its final phases at the
// multiplier, which end here.
#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "bezierpde/solvers/cmc/ceres_lm_options.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/optim/levenberg_marquardt.h"
#include "bezierpde/solvers/optim/trust_region_model.h"

namespace bpde::cmc_detail {
using namespace bpde::optim;  // the generic least squares and trust-region steps (solvers/optim)

namespace {
// Relative eigenvalue below which a mode is soft (measured: 21 … 136 soft modes of 63 … 243 on
// the cases of docs/cmc_algorithm.md, "The final phases").
constexpr double kSoftCut = 1e-4;
// Chord steps in the hard modes per evaluation, until the hard part of the gradient is below
// kHardFraction of ‖G‖; where they stop falling by 2x a step above hard_accept (kHardAccept of ‖G‖,
// or kHardNearTol below), the factor is renewed at the point (at most twice), and an evaluation
// that ends above it is rejected.
// 30 steps: far from the split point (|s| = 0.31 on the V form past the hemisphere, H = -0.99,
// n = 10) the chord steps contract by 2x or better but 10 were not enough, and every evaluation
// there was rejected (the phase ended with no step at 3.5e-9; with 30, 1.6e-11).
constexpr int kMaxHardSteps = 30;
constexpr double kHardFraction = 1e-6;
constexpr double kHardAccept = 1e-3;
// Near the tolerance the chord steps stop at the rounding of the gradient, which kHardAccept ‖G‖
// passes below as G falls (measured on the tensor catenoid at n = 10: the hard part stalls at
// 2.1e-13 … 3.6e-13 where 1e-3 ‖G‖ = 2.1e-13, and every evaluation past |s| = 4.5e-3 was
// rejected). So the hard part also counts as solved below this fraction of what ‖G‖ is at the
// tolerance (‖G‖ tol / r, r the relative residual). To first order its share of the first
// variation is then about a tenth of the tolerance (a first-order estimate: C maps the hard and
// soft coordinates with different gains), and G is less accurate for the reduced LM by up to 10 %
// near the tolerance. It cannot cause a false "converged": the point is kept by its true relative
// first variation (best_r_), evaluated in full.
constexpr double kHardNearTol = 0.1;
// Stall test: ‖G‖ falls by less than this factor in kStallWindow iterations. 100, not 30: with 30
// the sphere patch at n = 8 and 10 stopped while ‖G‖ still fell slowly towards a stationary point
// of its norm (now reached and reported: 5.1e-10 and 1.26e-11, was 1.9e-11 at n = 10), and the
// tensor catenoid at n = 8 at 9.6e-11 (now 1.3e-11, in 10-11 s instead of 4-5 s, where the phase
// reaches its cap of 10 x max_corrector_iterations = 300). The test can first fire after 100
// iterations, so with max_corrector_iterations <= 10 the cap always ends a phase that does not
// reach the tolerance or run out of steps first.
constexpr double kStallFactor = 0.9;
constexpr int kStallWindow = 100;
// Where no step lowers ‖G‖, it is called stationary only when ‖JᵀG‖ <= this × ‖J‖_F ‖G‖: G nearly
// orthogonal to the range of J, so that no direction descends. Measured at such ends: 2.3e-5 on
// the tensor catenoid at n = 6 (G along a singular vector of J with singular value 6e-12, the
// largest 1.5e-4; the rest is the rounding of G, ~6e-15), 7.9e-6 on the circle at n = 6,
// H = -0.9, solver ceres.
constexpr double kStationary = 1e-3;
// The phase starts only within this relative first variation: farther off (a failed continuation
// step) the hard modes are not converged and the phase would only cost time.
constexpr double kSoftPhaseStart = 1e-6;

// The trust-region part (minimise_trust_region): acceptance and radius updates (Nocedal–Wright,
// Algorithm 4.1, with the radius halved, not quartered, on a poor step: the valley is long and the
// steps that work are near the largest that do), the first radius relative to the size of the
// free points in the C-norm (about the net's centroid, so that it does not depend on where the
// surface lies), and the smallest relative to the first. kTrRegular: a step may not lower the smallest |x_u ∧ x_v| /
// mean at the nodes below this fraction of the start's: on the sphere triangle at n = 8 the descent otherwise ends at a
// critical point whose parametrisation degenerates (|x_u ∧ x_v| down to 4.5e-4 of its mean,
// measured), which mean-curvature-start finds too; the phase keeps to the regular surfaces near its start.
constexpr double kTrAccept = 0.1, kTrShrinkBelow = 0.25, kTrGrowAbove = 0.75;
constexpr double kFirstRadius = 1e-3, kTrSmallestRadius = 1e-12;
constexpr double kTrRegular = 0.25;

// The reduced system at the point p holds when it is built (the split point y0).
class SoftModeSystem {
 public:
  SoftModeSystem(AreaProblem& p, double H, double tolerance) : p_(p), H_(H), tol_(tolerance), y0_(p.get()) {
    best_y_ = y0_;
    best_r_ = p_.residual(H_);
    K_ = p_.hessian(H_);
    if (!K_.allFinite() || !std::isfinite(best_r_)) return;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K_, p_.dense_C());
    if (es.info() != Eigen::Success) return;
    const Eigen::VectorXd& lam = es.eigenvalues();
    lmax_ = lam.cwiseAbs().maxCoeff();
    if (!(lmax_ > 0) || !std::isfinite(lmax_)) return;
    std::vector<Eigen::Index> soft, hard;
    for (Eigen::Index i = 0; i < lam.size(); ++i) (std::abs(lam(i)) < kSoftCut * lmax_ ? soft : hard).push_back(i);
    if (soft.empty() || hard.empty()) return;
    Vs_ = es.eigenvectors()(Eigen::all, soft);
    Vh_ = es.eigenvectors()(Eigen::all, hard);
    h_ = Eigen::VectorXd::Zero(Vh_.cols());
    ok_ = linearise(/*fresh_hessian=*/false);  // K_ is the Hessian at this point already
    J0_ = J_;
    keep();
  }
  bool ok() const { return ok_; }
  Eigen::Index size() const { return Vs_.cols(); }
  /// The Schur complement at the split point (s = 0), from the constructor.
  const Eigen::MatrixXd& split_jacobian() const { return J0_; }
  /// G(s) into G and, when J is not null, the Schur complement at that point (which also renews
  /// the factor of the hard block for the chord steps). false when not finite. Leaves p at the
  /// point and keeps the point of smallest residual met.
  bool evaluate(const Eigen::VectorXd& s, Eigen::VectorXd& G, Eigen::MatrixXd* J) {
    if (!s.allFinite()) return false;
    // A failed evaluation leaves nothing behind: the next starts from the last good h and factor.
    if (!solve_hard(s, G, J)) {
      h_ = kept_h_;
      Khh_ = kept_Khh_;
      return false;
    }
    keep();
    return true;
  }
  double best_residual() const { return best_r_; }
  /// min |x_u ∧ x_v| / mean at the nodes (AreaForm::min_normal) of the point last evaluated.
  double min_normal() const { return p_.a->min_normal(p_.P()); }
  /// From now on a point counts as the best one only where min_normal() >= floor.
  void set_min_normal_floor(double floor) { min_normal_floor_ = floor; }
  const Eigen::VectorXd& best_point() const { return best_y_; }
  /// ‖JᵀG‖ / (‖J‖_F ‖G‖) at s (+inf when s cannot be evaluated): 0 at a stationary point of ‖G‖.
  double stationarity(const Eigen::VectorXd& s) {
    Eigen::VectorXd G;
    Eigen::MatrixXd J;
    if (!evaluate(s, G, &J)) return std::numeric_limits<double>::infinity();
    const double den = J.norm() * G.norm();
    return den > 0 ? (J.transpose() * G).norm() / den : 0.0;
  }

 private:
  void keep() {
    kept_h_ = h_;
    kept_Khh_ = Khh_;
  }
  bool solve_hard(const Eigen::VectorXd& s, Eigen::VectorXd& G, Eigen::MatrixXd* J) {
    double prev = std::numeric_limits<double>::infinity(), nh = 0;
    Eigen::VectorXd g;
    double r = 0;
    int refreshes = 0;
    for (int j = 0; j <= kMaxHardSteps; ++j) {
      p_.set(y0_ + Vs_ * s + Vh_ * h_);
      r = p_.residual(H_, &g);
      if (!std::isfinite(r)) return false;
      G = Vs_.transpose() * g;
      const Eigen::VectorXd gh = Vh_.transpose() * g;
      nh = gh.norm();
      if (nh <= kHardFraction * G.norm() || j == kMaxHardSteps) break;
      if (nh > 0.5 * prev) {
        // The chord steps stopped gaining: at the rounding floor (accepted below), or the factor
        // is from a point too far away: renew it here (at most twice).
        if (nh <= hard_accept(G.norm(), r) || refreshes++ >= 2 || !factor_hard()) break;
        prev = std::numeric_limits<double>::infinity();
      } else {
        prev = nh;
      }
      h_ -= Khh_.solve(gh);
    }
    // G is a function of s only when h(s) is solved: a point where it is not is out.
    if (!(nh <= hard_accept(G.norm(), r))) return false;
    // A point below the regularity floor (the trust-region part's) is never the best one.
    if (r < best_r_ && (min_normal_floor_ <= 0 || p_.a->min_normal(p_.P()) >= min_normal_floor_))
      best_r_ = r, best_y_ = p_.get();
    if (J) {
      if (!linearise()) return false;
      *J = J_;
    }
    return true;
  }

  // The hard part of the gradient that counts as solved, given ‖G‖ and the relative residual r:
  // kHardAccept of ‖G‖, or kHardNearTol of ‖G‖ scaled to the tolerance (‖G‖ tol / r).
  double hard_accept(double nG, double r) const {
    return std::max(kHardAccept * nG, r > 0 ? kHardNearTol * nG * tol_ / r : 0.0);
  }
  // The Hessian K (unless fresh_hessian is false: K_ is already the one at p's point) and the
  // factor of its hard block Khh at p's point.
  bool factor_hard(bool fresh_hessian = true) {
    if (fresh_hessian) K_ = p_.hessian(H_);
    if (!K_.allFinite()) return false;
    KVh_ = K_ * Vh_;
    // Khh is symmetric but indefinite where A_H is a saddle in hard modes (a cap past the
    // hemisphere is a critical point of A_H, not a minimum): LU with partial pivoting, not LDLᵀ.
    Khh_.compute(Vh_.transpose() * KVh_);
    // At the split point Vhᵀ K Vh is diag(λ_h) with |λ_h| >= kSoftCut λ_max: a pivot far below
    // that means the hard block lost its conditioning on the way.
    return Khh_.matrixLU().diagonal().cwiseAbs().minCoeff() > 1e-3 * kSoftCut * lmax_;
  }
  // The Schur complement J and the factor of Khh at p's point.
  bool linearise(bool fresh_hessian = true) {
    if (!factor_hard(fresh_hessian)) return false;
    const Eigen::MatrixXd Khs = KVh_.transpose() * Vs_;
    J_ = Vs_.transpose() * K_ * Vs_ - Khs.transpose() * Khh_.solve(Khs);
    return J_.allFinite();
  }

  AreaProblem& p_;
  double H_, tol_;
  Eigen::VectorXd y0_, h_, best_y_, kept_h_;
  Eigen::MatrixXd K_, KVh_, Vs_, Vh_, J_, J0_;
  Eigen::PartialPivLU<Eigen::MatrixXd> Khh_, kept_Khh_;
  double lmax_ = 0, best_r_ = std::numeric_limits<double>::infinity(), min_normal_floor_ = 0;
  bool ok_ = false;
};

// ‖G‖ of the accepted points, oldest first: stalled when it fell by less than 10 % over the last
// kStallWindow iterations.
bool soft_stalled(const std::vector<double>& history) {
  const size_t m = history.size();
  return m > kStallWindow && history[m - 1] > kStallFactor * history[m - 1 - kStallWindow];
}

struct SoftOutcome {
  int iterations = 0;
  bool stationary = false;
};

SoftOutcome minimise_newton(SoftModeSystem& sys, double tol, int max_iterations) {
  LeastSquaresProblem problem;
  problem.residuals = [&](const Eigen::VectorXd& s, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    if (!sys.evaluate(s, r, J)) {
      r = Eigen::VectorXd::Constant(sys.size(), std::numeric_limits<double>::quiet_NaN());
      if (J) *J = Eigen::MatrixXd::Constant(sys.size(), sys.size(), std::numeric_limits<double>::quiet_NaN());
    }
  };
  std::vector<double> history;
  problem.monitor = [&](const Eigen::VectorXd&, int, double phi) {
    history.push_back(std::sqrt(phi));
    return sys.best_residual() > tol && !soft_stalled(history);
  };
  LevenbergMarquardtOptions lo;
  lo.max_iterations = max_iterations;
  lo.marquardt_scaling = false;
  Eigen::VectorXd s = Eigen::VectorXd::Zero(sys.size());
  const LsOutcome lm = levenberg_marquardt(problem, s, lo);
  return {lm.iterations, lm.stop == LsStop::NoStep && sys.stationarity(s) <= kStationary};
}

// Trust-region Newton on φ(s) = A_H(y0 + Vs s + Vh h(s)), A_H along the floor of the valley
// (the hard modes solved): ∇φ = G (the hard part of the gradient vanishes), its Hessian the Schur
// complement J. The step minimises G·c + ½cᵀJc over ‖c‖ <= radius (trust_region_model.h); the
// change of φ along it is measured by Simpson's rule on G, ρ = that / the model's, and the step is
// taken when ρ > kTrAccept and the parametrisation stays as regular as kTrRegular of the start's.
// s is in C-orthonormal coordinates, so the radius is in the C-norm. Returns the steps tried and
// whether the regularity bound refused one.
struct TrustRegionOutcome {
  int iterations = 0;
  bool blocked = false;  ///< a step was refused by the regularity bound (and the tolerance not reached)
};

TrustRegionOutcome minimise_trust_region(SoftModeSystem& sys, double tol, int max_iterations, double radius) {
  TrustRegionOutcome out;
  const Eigen::Index n = sys.size();
  Eigen::VectorXd s = Eigen::VectorXd::Zero(n), G, Gm, G1;
  Eigen::MatrixXd J;
  if (!sys.evaluate(s, G, &J)) return out;
  const double regular = kTrRegular * sys.min_normal();
  sys.set_min_normal_floor(regular);
  int& it = out.iterations;
  const double smallest = kTrSmallestRadius * radius;
  while (it < max_iterations && sys.best_residual() > tol && radius > smallest) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (J + J.transpose()));
    if (es.info() != Eigen::Success) break;
    const TrustRegionModel m{es.eigenvalues(), es.eigenvectors().transpose() * G, es.eigenvectors()};
    const Eigen::VectorXd c = m.step(radius);
    const double pred = m.decrease(c);
    if (!(c.allFinite() && pred > 0)) break;
    ++it;
    const Eigen::VectorXd ds = m.V * c;
    bool ok = sys.evaluate(s + 0.5 * ds, Gm, nullptr) && sys.evaluate(s + ds, G1, nullptr);
    if (ok && !(sys.min_normal() >= regular)) {
      ok = false;
      out.blocked = true;
    }
    const double rho = ok ? -simpson_change(G, Gm, G1, ds) / pred : -std::numeric_limits<double>::infinity();
    if (rho > kTrAccept) {
      s += ds;
      if (!sys.evaluate(s, G, &J)) break;
    }
    if (!(rho >= kTrShrinkBelow))
      radius = 0.5 * c.norm();
    else if (rho > kTrGrowAbove && c.norm() > 0.99 * radius)
      radius *= 2;
  }
  out.blocked = out.blocked && sys.best_residual() > tol;
  return out;
}

// G(s) as one Ceres residual block on one parameter block, divided by `scale`.
class ReducedFirstVariation final : public ceres::CostFunction {
 public:
  ReducedFirstVariation(SoftModeSystem* sys, double scale) : sys_(sys), scale_(scale) {
    set_num_residuals(static_cast<int>(sys->size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(sys->size()));
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Index n = sys_->size();
    const Eigen::Map<const Eigen::VectorXd> s(parameters[0], n);
    Eigen::VectorXd G;
    Eigen::MatrixXd J;
    const bool want_j = jacobians && jacobians[0];
    if (!sys_->evaluate(s, G, want_j ? &J : nullptr)) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, n) = G / scale_;
    if (want_j)  // Ceres wants the Jacobian row-major
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(jacobians[0], n, n) = J / scale_;
    return true;
  }

 private:
  SoftModeSystem* sys_;
  double scale_;
};

class SoftStop final : public ceres::IterationCallback {
 public:
  SoftStop(const SoftModeSystem* sys, double tol, double scale) : sys_(sys), tol_(tol), scale_(scale) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
    if (sys_->best_residual() <= tol_) {
      reached = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (it.step_is_successful) history_.push_back(std::sqrt(2 * it.cost) * scale_);
    if (soft_stalled(history_)) {
      stall = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool reached = false, stall = false;

 private:
  const SoftModeSystem* sys_;
  double tol_, scale_;
  std::vector<double> history_;
};

SoftOutcome minimise_ceres(SoftModeSystem& sys, double tol, int max_iterations) {
  const Eigen::Index n = sys.size();
  const double scale = sys.split_jacobian().colwise().norm().maxCoeff();
  if (!(scale > 0) || !std::isfinite(scale)) return {};
  Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
  ceres::Problem problem;
  problem.AddResidualBlock(new ReducedFirstVariation(&sys, scale), nullptr, s.data());  // owned by problem
  ceres::Solver::Options so = ceres_lm_options(max_iterations);
  so.jacobi_scaling = false;  // with diag JᵀJ clamped to [1, 1]: D = Id, Levenberg's scaling
  so.min_lm_diagonal = 1.0;
  so.max_lm_diagonal = 1.0;
  SoftStop cb(&sys, tol, scale);
  so.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  SoftOutcome out;
  out.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);  // steps tried
  // Ceres's own tests (its trust region collapsed, the step vanished) end in CONVERGENCE; a
  // FAILURE (an evaluation failed) says nothing about stationarity.
  out.stationary = !cb.reached && !cb.stall && summary.termination_type == ceres::CONVERGENCE &&
                   sys.stationarity(s) <= kStationary;
  return out;
}

}  // namespace

CorrectorStats area_soft_mode_phase(AreaProblem& p, double H, const CmcOptions& o, int max_iterations) {
  CorrectorStats st;
  const double e0 = p.eps;
  p.eps = 0.0;
  st.residual = p.residual(H);
  if (std::isfinite(st.residual) && st.residual > o.tolerance && st.residual <= kSoftPhaseStart &&
      max_iterations > 0) {
    SoftModeSystem sys(p, H, o.tolerance);
    if (sys.ok()) {
      const SoftOutcome r = o.solver == CmcSolver::Ceres ? minimise_ceres(sys, o.tolerance, max_iterations)
                                                         : minimise_newton(sys, o.tolerance, max_iterations);
      st.iterations = r.iterations;
      st.soft_stationary = r.stationary;
    }
    p.set(sys.best_point());
    st.residual = sys.best_residual();
    if (o.area_trust_region && sys.ok() && st.residual > o.tolerance && std::isfinite(st.residual)) {
      // Trust-region Newton on A_H along the valley floor, from a new split at the best point.
      const Eigen::VectorXd y0 = p.get();
      SoftModeSystem tr(p, H, o.tolerance);
      if (tr.ok()) {
        // The size of the free points about the net's centroid, in the C-norm.
        const Eigen::RowVector3d centroid = p.P().colwise().mean();
        Eigen::VectorXd y = p.get();
        for (Eigen::Index i = 0; i < y.size(); ++i) y(i) -= centroid(i % 3);
        const double radius = kFirstRadius * std::sqrt(std::max(y.dot(p.dense_C() * y), 0.0));
        const TrustRegionOutcome t = minimise_trust_region(tr, o.tolerance, max_iterations, radius);
        st.trust_region_iterations = t.iterations;
        st.iterations += t.iterations;
        st.trust_region_blocked = t.blocked;
        // The best regular point met, which is the start where nothing was better (evaluate moves
        // p). Where the descent ended at the regularity bound above the tolerance, the start: the
        // points it lowered the first variation at lie on the way to a degenerate
        // parametrisation, and their surface is worse where it counts (the sphere triangle at
        // n = 8: 8.0e-11, but the mean curvature on the grid 0.812 … 1.017 against 0.977 … 1.002
        // at the start, the distance to the sphere the same).
        const bool keep_start = t.blocked && !(tr.best_residual() <= o.tolerance);
        p.set(keep_start ? y0 : tr.best_point());
        if (!keep_start && tr.best_residual() < st.residual) {
          st.residual = tr.best_residual();
          st.soft_stationary = false;
        }
      }
    }
  }
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  p.eps = e0;
  return st;
}

}  // namespace bpde::cmc_detail
