// The soft-mode phase of the area functional (cmc_area_problem.h, area_soft_mode_newton;
// docs/cmc.md, "The soft-mode phase").
//
// The method. At the point y0 where the truncated Newton phase stops, split the free coordinates
// by the generalised eigenproblem K v = λ C v (K the Hessian of A_H, C the Dirichlet Gram over the
// free points ⊗ Id_3, eigenvectors C-orthonormal): the soft modes Vs (|λ| < 1e-4 max|λ|: the
// nearly tangential, reparametrisation-like directions) and the hard modes Vh. Write
// y = y0 + Vs s + Vh h. For each s the hard equations Vhᵀ∇A_H(y) = 0 are well conditioned (their
// Hessian Vhᵀ K Vh has eigenvalues ≥ 1e-4 max|λ|) and are solved for h(s) by chord Newton steps
// (the factor of Vhᵀ K Vh from the last accepted point); what is left is the reduced first
// variation G(s) = Vsᵀ∇A_H(y0 + Vs s + Vh h(s)), whose Jacobian is the Schur complement
// J = Kss − Ksh Khh⁻¹ Khs (K in the split basis, at the point). The phase minimises ‖G‖² over s
// with the library's Levenberg–Marquardt loop (levenberg_marquardt.h) with geodesic acceleration
// and Levenberg's scaling (D = max diag JᵀJ · Id: s is in C-orthonormal coordinates, so the
// damping is a trust region in the C-norm, as the corrector's μC).
//
// Why. Measured at the end of stalled solves (docs/cmc.md, "The soft-mode phase"): J has singular
// values down to 6e-12 (its largest 1.5e-4 on the tensor catenoid at n = 6), so the Newton step in
// the soft modes is long (|d|_C = 2.6 there), while G(s) is quadratic in s on a far smaller scale: with the
// hard modes eliminated exactly, ‖G‖ along the Newton direction rises from 1e-3 of the step on.
// The whole-space methods (the corrector, the truncated phase) do not separate the two scales. On
// the reduced system the loop moves s by up to 0.08 (C-norm; probe) and takes the Fig. 1 circle at
// H = −0.9 from 1.7e-10 (n = 8) and 5.9e-11 (n = 10) to below the tolerance 1e-11.
//
// It stops at the tolerance (max-norm relative residual, the solve's measure), after
// max_iterations, when ‖G‖ falls by less than 10 % in 30 iterations, or when no step lowers ‖G‖
// (30 trials with growing damping: LsStop::NoStep). In the last case Jᵀ G ≈ 0 to rounding: G lies
// along the nearly null directions of the reduced Hessian, a stationary point of ‖G‖ that is not a
// critical point of A_H (soft_stationary; cmc_area.cpp words the message). It leaves p at the point
// with the smallest residual it met.
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "bezierpde/solvers/cmc/cmc_area_problem.h"
#include "bezierpde/solvers/cmc/levenberg_marquardt.h"

namespace bpde::cmc_detail {

namespace {
// Relative eigenvalue below which a mode is soft (measured: 21 … 136 soft modes of 63 … 243 on
// the cases of docs/cmc.md, "The soft-mode phase").
constexpr double kSoftCut = 1e-4;
// Chord steps in the hard modes per evaluation.
constexpr int kMaxHardSteps = 10;
// Stall test: ‖G‖ falls by less than this factor in kStallWindow iterations.
constexpr double kStallFactor = 0.9;
constexpr int kStallWindow = 30;
}  // namespace

CorrectorStats area_soft_mode_newton(AreaProblem& p, double H, const CmcOptions& o, int max_iterations) {
  CorrectorStats st;
  const double e0 = p.eps;
  p.eps = 0.0;
  const Eigen::VectorXd y0 = p.get();
  Eigen::VectorXd best_y = y0;
  st.residual = p.residual(H);
  auto finish = [&]() {
    p.set(best_y);
    st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
    p.eps = e0;
    return st;
  };
  if (!std::isfinite(st.residual) || st.residual <= o.tolerance || max_iterations <= 0) return finish();
  Eigen::MatrixXd K = p.hessian(H);
  if (!K.allFinite()) return finish();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, p.C);
  if (es.info() != Eigen::Success) return finish();
  const Eigen::VectorXd& lam = es.eigenvalues();
  const double lmax = lam.cwiseAbs().maxCoeff();
  if (!(lmax > 0) || !std::isfinite(lmax)) return finish();
  std::vector<Eigen::Index> soft, hard;
  for (Eigen::Index i = 0; i < lam.size(); ++i) (std::abs(lam(i)) < kSoftCut * lmax ? soft : hard).push_back(i);
  if (soft.empty() || hard.empty()) return finish();
  const Eigen::MatrixXd Vs = es.eigenvectors()(Eigen::all, soft), Vh = es.eigenvectors()(Eigen::all, hard);
  const Eigen::Index ns = Vs.cols();

  // A point of the reduced problem: s, h(s), the gradient there, G = Vsᵀg, the residual.
  struct Point {
    Eigen::VectorXd s, h, g, G;
    double r = std::numeric_limits<double>::infinity();
  };
  // At accepted points: the Schur complement J and the factor of Khh for the chord steps.
  // Khh is symmetric but indefinite where A_H is a saddle in hard modes (a cap past the
  // hemisphere is a critical point of A_H, not a minimum): LU with partial pivoting, not LDLᵀ.
  Eigen::PartialPivLU<Eigen::MatrixXd> Khh;
  Eigen::MatrixXd J;
  auto linearise = [&]() {
    K = p.hessian(H);
    if (!K.allFinite()) return false;
    const Eigen::MatrixXd KVh = K * Vh;
    Khh.compute(Vh.transpose() * KVh);
    // At the split point Vhᵀ K Vh is diag(λ_h) with |λ_h| >= kSoftCut λ_max: a pivot far below
    // that means the hard block lost its conditioning on the way.
    if (!(Khh.matrixLU().diagonal().cwiseAbs().minCoeff() > 1e-3 * kSoftCut * lmax)) return false;
    const Eigen::MatrixXd Khs = KVh.transpose() * Vs;
    J = Vs.transpose() * K * Vs - Khs.transpose() * Khh.solve(Khs);
    return J.allFinite();
  };
  // h(s) by chord steps with the current factor of Khh, from the warm start x.h; p is left at x.
  auto evaluate = [&](Point& x) {
    double prev = std::numeric_limits<double>::infinity();
    for (int j = 0; j <= kMaxHardSteps; ++j) {
      p.set(y0 + Vs * x.s + Vh * x.h);
      x.r = p.residual(H, &x.g);
      if (!std::isfinite(x.r)) return false;
      x.G = Vs.transpose() * x.g;
      const double nh = (Vh.transpose() * x.g).norm();
      // The hard part is negligible in ‖G‖, or the chord steps stop gaining.
      if (nh <= 1e-3 * x.G.norm() || nh > 0.5 * prev || j == kMaxHardSteps) break;
      prev = nh;
      x.h -= Khh.solve(Vh.transpose() * x.g);
    }
    return true;
  };

  // The reduced problem for the library's Levenberg–Marquardt loop (levenberg_marquardt.h): x = s,
  // r = G(s), its Jacobian J(s). The hard part h is carried from one evaluation to the next.
  Point at;
  at.h = Eigen::VectorXd::Zero(Vh.cols());
  bool linear_ok = linearise();
  LeastSquaresProblem problem;
  problem.residuals = [&](const Eigen::VectorXd& sv, Eigen::VectorXd& r, Eigen::MatrixXd* Jout) {
    at.s = sv;
    if (!linear_ok || !evaluate(at)) {
      r = Eigen::VectorXd::Constant(ns, std::numeric_limits<double>::quiet_NaN());
      if (Jout) *Jout = Eigen::MatrixXd::Constant(ns, ns, std::numeric_limits<double>::quiet_NaN());
      return;
    }
    r = at.G;
    if (Jout) {
      linear_ok = linearise();
      *Jout = linear_ok ? J : Eigen::MatrixXd::Constant(ns, ns, std::numeric_limits<double>::quiet_NaN());
    }
  };
  std::vector<double> history;
  problem.monitor = [&](const Eigen::VectorXd&, int, double phi) {
    // p is at the point just evaluated with its Jacobian: the accepted one.
    if (at.r < st.residual) best_y = p.get(), st.residual = at.r;
    history.push_back(std::sqrt(phi));
    const size_t m = history.size();
    const bool stall = m > kStallWindow && history[m - 1] > kStallFactor * history[m - 1 - kStallWindow];
    return st.residual > o.tolerance && !stall;
  };
  LevenbergMarquardtOptions lo;
  lo.max_iterations = max_iterations;
  lo.marquardt_scaling = false;
  Eigen::VectorXd sv = Eigen::VectorXd::Zero(ns);
  const LsOutcome lm = levenberg_marquardt(problem, sv, lo);
  st.iterations = lm.iterations;
  st.soft_stationary = lm.stop == LsStop::NoStep;
  return finish();
}

}  // namespace bpde::cmc_detail
