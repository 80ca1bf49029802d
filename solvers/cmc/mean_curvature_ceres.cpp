// Solver "ceres" of the least-squares mean-curvature functional (mean_curvature_minimise.h):
// Φ = Σ_q r_q² (mean_curvature_least_squares.h) as ONE residual block per node q of the quadrature
// rule, all on one parameter block y = the free control points (3 per point, point-major: y[3a + c]
// is coordinate c of point free[a]), minimised by ceres::Solve (Levenberg–Marquardt, dense normal
// Cholesky). Ceres's cost is ½Φ.
//
// Every r_q depends on every free point (the Bernstein basis has global support), so each block's
// Jacobian is a dense 1 × 3k row: ∂r_q/∂y[3a + c] = Σ_t ∂r_q/∂(∂_t x)_c · ∂_t B_{free[a]}(u_q, v_q),
// the first factor by ceres::Jet on the surface jet at the node (node_residual), the second from the
// basis tables (basis_derivative), t over x_u, x_v, x_uu, x_uv, x_vv. The surface derivatives at all
// nodes (one product of the basis tables with the net) are computed once per point y and shared by
// the blocks (NodeCache), so an evaluation costs what the newton route's does. Ceres runs
// single-threaded here (the cache is not shared between threads).
//
// The V form (H an unknown, V(P) = V0): a second parameter block, H (∂r_q/∂H = −√(w_q ρ_q |N_q|),
// MeanCurvatureLeastSquares::h_derivative), and the free points on a ceres::Manifold, the level set
// V = V0 (VolumeManifold below): Ceres steps in its tangent space ∇V⊥ (3k − 1 directions, an
// orthonormal basis from the Householder reflection of ∇V) and each trial point is put back on
// V = V0 along ∇V (restore_volume, as the newton route does), so every point Ceres evaluates is
// feasible. Ceres has no equality constraints; a manifold is how it takes one.
//
// Stopping: an IterationCallback ends the solve when √Φ <= target or Φ stalls (the tests of the
// newton route, mean_curvature_minimise.h); Ceres's own function, gradient and parameter tolerances
// are set out of the way, so they do not stop it earlier.
#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>

#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "bezierpde/solvers/cmc/ceres_lm_options.h"
#include "bezierpde/solvers/cmc/mean_curvature_minimise.h"

namespace bpde::cmc_detail {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The node derivatives at the last point y evaluated, and the basis derivatives restricted to the
// free points (row q of B[t] is ∂_t B_{free[a]}(u_q, v_q), a = 0..k−1).
class NodeCache {
 public:
  NodeCache(const MeanCurvatureLeastSquares& f, const Eigen::MatrixX3d& P, const std::vector<int>& free, bool with_H)
      : f_(f), P_(P), free_(free), with_H_(with_H) {
    for (int t = 0; t < 5; ++t) B_[size_t(t)] = f.basis_derivative(t)(Eigen::all, free);
  }
  int unknowns() const { return 3 * static_cast<int>(free_.size()); }
  const MeanCurvatureLeastSquares& form() const { return f_; }
  const RowMatrix& basis(int t) const { return B_[size_t(t)]; }
  bool with_H() const { return with_H_; }
  /// ∂r/∂H at the nodes for the last point passed to at() (the V form only).
  const Eigen::VectorXd& h_derivative() const { return dH_; }
  /// The node derivatives at y (recomputed when y differs from the last point), or nullptr when y is
  /// not finite.
  const MeanCurvatureLeastSquares::NodeDerivatives* at(const double* y) {
    const size_t bytes = sizeof(double) * size_t(unknowns());
    if (!(valid_ && std::memcmp(last_.data(), y, bytes) == 0)) {
      last_.assign(y, y + unknowns());
      for (size_t a = 0; a < free_.size(); ++a)
        for (int c = 0; c < 3; ++c) P_(free_[a], c) = y[3 * a + size_t(c)];
      finite_ = P_.allFinite();
      if (finite_) X_ = f_.derivatives(P_);
      if (finite_ && with_H_) dH_ = f_.h_derivative(X_);
      valid_ = true;
    }
    return finite_ ? &X_ : nullptr;
  }

 private:
  const MeanCurvatureLeastSquares& f_;
  Eigen::MatrixX3d P_;
  const std::vector<int>& free_;
  std::array<RowMatrix, 5> B_;
  std::vector<double> last_;
  bool with_H_, valid_ = false, finite_ = false;
  MeanCurvatureLeastSquares::NodeDerivatives X_;
  Eigen::VectorXd dH_;
};

// r_q, one residual on the parameter block y and, in the V form, on the block H.
class NodeResidual final : public ceres::CostFunction {
 public:
  NodeResidual(NodeCache* cache, Eigen::Index q, double H) : cache_(cache), q_(q), H_(H) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(cache->unknowns());
    if (cache->with_H()) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const MeanCurvatureLeastSquares::NodeDerivatives* X = cache_->at(parameters[0]);
    if (!X) return false;
    const double H = cache_->with_H() ? parameters[1][0] : H_;
    if (!std::isfinite(H)) return false;
    if (jacobians && cache_->with_H() && jacobians[1]) jacobians[1][0] = cache_->h_derivative()(q_);
    const bool jac = jacobians && jacobians[0];
    Eigen::Matrix<double, 15, 1> dr;
    const double r = cache_->form().node_residual(*X, q_, H, jac ? &dr : nullptr);
    if (!std::isfinite(r)) return false;
    residuals[0] = r;
    if (jac) {
      if (!dr.allFinite()) return false;
      const Eigen::Index k = cache_->unknowns() / 3;
      Eigen::Map<Eigen::Matrix<double, 3, Eigen::Dynamic>> row(jacobians[0], 3, k);  // column a = point free[a]
      row.noalias() = dr.segment<3>(0) * cache_->basis(0).row(q_);
      for (int t = 1; t < 5; ++t) row.noalias() += dr.segment<3>(3 * t) * cache_->basis(t).row(q_);
    }
    return true;
  }

 private:
  NodeCache* cache_;
  Eigen::Index q_;
  double H_;
};

// The level set V = V0 of the free coordinates y (ambient 3k, tangent 3k − 1). At y the tangent
// space is ∇V(y)⊥, with the orthonormal basis T(y): columns 1 … 3k − 1 of the Householder
// reflection Q that maps e_0 to ±∇V/|∇V|. Plus(y, δ) = restore_volume(y + T(y)δ) (false when that
// fails: Ceres then rejects the step), PlusJacobian = T(y); Minus(z, y) = T(y)ᵀ(z − y), the
// inverse of Plus to first order, MinusJacobian = T(y)ᵀ. T is cached for the last y.
class VolumeManifold final : public ceres::Manifold {
 public:
  VolumeManifold(const VolumeTarget& vt, const Eigen::MatrixX3d& P, const std::vector<int>& free)
      : vt_(vt), P_(P), free_(free), k_(3 * static_cast<int>(free.size())) {}
  int AmbientSize() const override { return k_; }
  int TangentSize() const override { return k_ - 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const Eigen::MatrixXd* T = basis(x);
    if (!T) return false;
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(x, k_) + *T * Eigen::Map<const Eigen::VectorXd>(delta, k_ - 1);
    set(y.data());
    if (!restore_volume(vt_, P_, free_) || !P_.allFinite()) return false;
    for (size_t a = 0; a < free_.size(); ++a)
      for (int c = 0; c < 3; ++c) x_plus_delta[3 * a + size_t(c)] = P_(free_[a], c);
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const override {
    const Eigen::MatrixXd* T = basis(x);
    if (!T) return false;
    Eigen::Map<RowMatrix>(jacobian, k_, k_ - 1) = *T;
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    const Eigen::MatrixXd* T = basis(x);
    if (!T) return false;
    Eigen::Map<Eigen::VectorXd>(y_minus_x, k_ - 1) =
        T->transpose() * (Eigen::Map<const Eigen::VectorXd>(y, k_) - Eigen::Map<const Eigen::VectorXd>(x, k_));
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const override {
    const Eigen::MatrixXd* T = basis(x);
    if (!T) return false;
    Eigen::Map<RowMatrix>(jacobian, k_ - 1, k_) = T->transpose();
    return true;
  }

 private:
  void set(const double* y) const {
    for (size_t a = 0; a < free_.size(); ++a)
      for (int c = 0; c < 3; ++c) P_(free_[a], c) = y[3 * a + size_t(c)];
  }
  // T(x), or nullptr when ∇V(x) is 0 or not finite.
  const Eigen::MatrixXd* basis(const double* x) const {
    const size_t bytes = sizeof(double) * size_t(k_);
    if (!(last_.size() == size_t(k_) && std::memcmp(last_.data(), x, bytes) == 0)) {
      last_.assign(x, x + k_);
      set(x);
      const Eigen::MatrixX3d G = vt_.form.gradient_rows(P_, free_);
      Eigen::VectorXd g(k_);
      for (size_t a = 0; a < free_.size(); ++a) g.segment<3>(3 * Eigen::Index(a)) = G.row(Eigen::Index(a)).transpose();
      ok_ = g.allFinite() && g.squaredNorm() > 0;
      if (ok_) {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
        const Eigen::MatrixXd Q = qr.householderQ();
        T_ = Q.rightCols(k_ - 1);
      }
    }
    return ok_ ? &T_ : nullptr;
  }
  const VolumeTarget& vt_;
  mutable Eigen::MatrixX3d P_;
  const std::vector<int>& free_;
  int k_;
  mutable std::vector<double> last_;
  mutable bool ok_ = false;
  mutable Eigen::MatrixXd T_;
};

class StopAtTarget final : public ceres::IterationCallback {
 public:
  // y: the parameter block, which Ceres updates at every iteration (update_state_every_iteration).
  // h: the H block (the V form; Ceres updates it too), or the fixed H. With check (the finer rule)
  // and P (a net whose free rows are y's), the rules are compared every kRuleCheckEvery accepted
  // steps (rules_agree, mean_curvature_minimise.h).
  StopAtTarget(double target, const ProgressFn& progress, const std::vector<double>& y, const double& h,
               const MeanCurvatureLeastSquares* check, const Eigen::MatrixX3d& P, const std::vector<int>& free)
      : target_(target), progress_(progress), y_(y), h_(h), check_(check), P_(P), free_(free), best(y), best_h(h),
        agreed_(y), agreed_h_(h) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    // After a rejected step s.cost is the rejected candidate's (Ceres 2.1), so only accepted
    // points (and the start, iteration 0, which counts as successful) are tested.
    if (!s.step_is_successful) return ceres::SOLVER_CONTINUE;
    const double phi = 2.0 * s.cost;
    best = y_;  // Ceres puts the start back if it ends in FAILURE; the caller keeps this point instead
    best_h = h_;
    if (check_ && s.iteration > 0 && ++accepted_ % kRuleCheckEvery == 0) {
      for (size_t a = 0; a < free_.size(); ++a)
        for (int c = 0; c < 3; ++c) P_(free_[a], c) = y_[3 * a + size_t(c)];
      if (!rules_agree(*check_, P_, h_, phi, target_)) {
        interrupted = true;
        best = agreed_;
        best_h = agreed_h_;
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
      agreed_ = y_;
      agreed_h_ = h_;
    }
    if (s.iteration == 0) start_ = std::sqrt(phi);
    last11_.push_back(phi);
    if (last11_.size() > 11) last11_.erase(last11_.begin());
    if (s.iteration > 0) report(progress_, "cmc least squares", ls_fraction(start_, target_, std::sqrt(phi)), 1);
    if (std::sqrt(phi) <= target_) {
      reached = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (stalled(last11_)) {
      stall = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool reached = false, stall = false, interrupted = false;

 private:
  double target_, start_ = 0.0;
  const ProgressFn& progress_;
  const std::vector<double>& y_;
  const double& h_;
  const MeanCurvatureLeastSquares* check_;
  Eigen::MatrixX3d P_;
  const std::vector<int>& free_;

 public:
  std::vector<double> best;  ///< the last accepted point
  double best_h;             ///< and its H

 private:
  std::vector<double> last11_;
  std::vector<double> agreed_;
  double agreed_h_;
  int accepted_ = 0;
};

}  // namespace

LsOutcome minimise_ceres(const MeanCurvatureLeastSquares& f, const MeanCurvatureLeastSquares* check,
                         Eigen::MatrixX3d& P, const std::vector<int>& free, double& H, const VolumeTarget* vt,
                         double target, int max_iterations, const ProgressFn& progress) {
  LsOutcome out;
  report(progress, "cmc least squares", 0, 1);
  if (vt) {  // on a copy: a start that cannot be restored is reported as it was given
    Eigen::MatrixX3d Pr = P;
    if (!restore_volume(*vt, Pr, free)) {
      out.stop = LsStop::ConstraintUnmet;
      report(progress, "cmc least squares", 1, 1);
      return out;
    }
    P = std::move(Pr);
  }
  NodeCache cache(f, P, free, vt != nullptr);
  std::vector<double> y(size_t(cache.unknowns()));
  for (size_t a = 0; a < free.size(); ++a)
    for (int c = 0; c < 3; ++c) y[3 * a + size_t(c)] = P(free[a], c);
  double h = H;
  ceres::Problem problem;  // owns the cost functions and the manifold
  if (vt) {
    problem.AddParameterBlock(y.data(), cache.unknowns(), new VolumeManifold(*vt, P, free));
    problem.AddParameterBlock(&h, 1);
  }
  for (Eigen::Index q = 0; q < f.nodes(); ++q) {
    if (vt)
      problem.AddResidualBlock(new NodeResidual(&cache, q, H), nullptr, y.data(), &h);
    else
      problem.AddResidualBlock(new NodeResidual(&cache, q, H), nullptr, y.data());
  }

  ceres::Solver::Options so = ceres_lm_options(max_iterations);
  so.update_state_every_iteration = true;
  StopAtTarget cb(target, progress, y, h, check, P, free);
  so.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  for (size_t a = 0; a < free.size(); ++a)
    for (int c = 0; c < 3; ++c) P(free[a], c) = cb.best[3 * a + size_t(c)];
  if (vt) H = cb.best_h;
  // steps tried (Ceres's iteration 0 is the start's evaluation, counted as a successful step)
  out.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  if (cb.interrupted)
    out.stop = LsStop::Interrupted;
  else if (cb.reached)
    out.stop = LsStop::Reached;
  else if (cb.stall)
    out.stop = LsStop::Stalled;
  else if (summary.termination_type == ceres::NO_CONVERGENCE)
    out.stop = LsStop::MaxIterations;
  else if (!std::isfinite(f.value(P, H)))
    out.stop = LsStop::NonFinite;  // Ceres could not evaluate the start (FAILURE)
  else
    out.stop = LsStop::NoStep;  // the trust region collapsed (CONVERGENCE) or the step solve failed (FAILURE)
  report(progress, "cmc least squares", 1, 1);
  return out;
}

}  // namespace bpde::cmc_detail
