// Ceres corrector of the CMC continuation (solvers/cmc/cmc.h): Levenberg–Marquardt on the residuals
// F of triangular CMC eq. (11), with the analytic Jacobian (the exact Hessian of D_H over the free
// control points); the same for the first variation of A_H = A + 2HV (area/area_problem.h), whose
// Jacobian is the exact Hessian of A_H by quadrature. All 3k residuals and the 3k unknowns form ONE residual block on ONE parameter
// block, so Ceres sees the dense Jacobian as it is (one copy per evaluation) instead of k^2 small
// 3x3 blocks, and solves the LM step with a dense solver (kLinearSolver below; measured in
// docs/performance_measurements.md, "CMC solvers (D_H)"). Ceres runs single-threaded here.
#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>

#include <cmath>
#include <functional>
#include <memory>

#include "bezierpde/solvers/cmc/ceres_lm_options.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {
namespace {

// DENSE_NORMAL_CHOLESKY: the LM step from J^T J + D by a dense Cholesky (Eigen), a third of the
// flops of DENSE_QR on the augmented 6k x 3k matrix. It squares the conditioning of the Bernstein
// Hessian, which costs at most an extra LM iteration at the degrees of the tests; measured against
// DENSE_QR in docs/performance_measurements.md ("CMC solvers (D_H)").
constexpr ceres::LinearSolverType kLinearSolver = ceres::DENSE_NORMAL_CHOLESKY;

// The stopping test of the callback: the residual of eq. (11) as the newton corrector computes it
// (the exact denominator only when the residual may be within 1e3 x tolerance, else the last one;
// CmcProblem::evaluate), so both stop at the same test; the area problem computes it whole. F
// receives the residual vector (the free gradient) of the same evaluation.
double stop_residual(CmcProblem& p, double H, double tol, double& scale, Eigen::VectorXd& F) {
  return p.evaluate(H, F, tol, scale, &scale);
}
double stop_residual(AreaProblem& p, double H, double, double&, Eigen::VectorXd& F) { return p.residual(H, &F); }

// The residuals of a point come with its stopping test (one evaluation), which the callback reads
// for the accepted point instead of evaluating the residual there again.
template <class Problem>
class AllResiduals final : public ceres::CostFunction {
 public:
  AllResiduals(Problem* p, double H, double tol) : p_(p), H_(H), tol_(tol) {
    set_num_residuals(3 * p->k());
    mutable_parameter_block_sizes()->push_back(3 * p->k());
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int n = 3 * p_->k();
    const Eigen::Map<const Eigen::VectorXd> y(parameters[0], n);
    if (!y.allFinite()) return false;
    Eigen::Map<Eigen::VectorXd> F(residuals, n);
    // Ceres evaluates the residuals at a candidate point and, when it accepts the step, the
    // residuals and the Jacobian at the same point again: the residuals are reused.
    if (!(last_y_.size() == n && last_y_ == y)) {
      p_->set(y);
      last_y_ = y;
      last_r_ = stop_residual(*p_, H_, tol_, scale_, last_F_);
    }
    F = last_F_;
    if (!F.allFinite()) return false;
    if (jacobians && jacobians[0]) {
      // Ceres wants the Jacobian row-major.
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(jacobians[0], n, n);
      // At a point that meets the tolerance the callback ends the solve before the Jacobian is
      // used (Ceres runs the callbacks right after this evaluation, before its own tests), so
      // the Hessian is not assembled there; Ceres requires the Jacobian written, hence zeros.
      if (last_r_ <= tol_) {
        J.setZero();
        return true;
      }
      p_->set(y);
      J = p_->hessian(H_);
      if (!J.allFinite()) return false;
    }
    return true;
  }
  /// The stopping residual of y when y was the last point evaluated, else -1.
  double residual_of(const Eigen::VectorXd& y) const {
    return last_y_.size() == y.size() && last_y_ == y ? last_r_ : -1.0;
  }

 private:
  Problem* p_;
  double H_, tol_;
  mutable Eigen::VectorXd last_y_, last_F_;
  mutable double last_r_ = 0.0, scale_ = 0.0;
};

template <class Problem>
class StopAtTolerance final : public ceres::IterationCallback {
 public:
  StopAtTolerance(Problem* p, const AllResiduals<Problem>* f, const Eigen::VectorXd* buf, double H, double tol)
      : p_(p), f_(f), buf_(buf), H_(H), tol_(tol) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    double r = f_->residual_of(*buf_);
    if (r < 0.0) {  // the current point is not the last one evaluated (after a rejected step)
      p_->set(*buf_);
      Eigen::VectorXd F;
      r = stop_residual(*p_, H_, tol_, scale_, F);
    }
    return r <= tol_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  Problem* p_;
  const AllResiduals<Problem>* f_;
  const Eigen::VectorXd* buf_;
  double H_, tol_, scale_ = 0.0;
};

template <class Problem>
CorrectorStats ceres_correct_impl(Problem& p, double H, const CmcOptions& o) {
  CorrectorStats st = start_stats(p, H, o);
  if (st.ok || !std::isfinite(st.residual)) return st;
  Eigen::VectorXd buf = p.get();
  ceres::Problem::Options po;
  ceres::Problem problem(po);
  auto* f = new AllResiduals<Problem>(&p, H, o.tolerance);  // owned by problem
  problem.AddResidualBlock(f, nullptr, buf.data());

  ceres::Solver::Options so = ceres_lm_options(o.max_corrector_iterations);
  so.linear_solver_type = kLinearSolver;
  // J is square and non-singular on the branch: start as Gauss–Newton (= Newton on eq. (11)).
  so.initial_trust_region_radius = 1e12;
  so.max_trust_region_radius = 1e16;
  so.update_state_every_iteration = true;
  StopAtTolerance<Problem> cb(&p, f, &buf, H, o.tolerance);
  so.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  p.set(buf);
  st.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  st.residual = p.residual(H);
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  return st;
}

// The V form: residuals (g, c/|∇V|) with g = ∇F_ε + 2H∇V over the free points and c = V − V0, on
// the parameter blocks Y (3k) and H (1).
class BorderedResiduals final : public ceres::CostFunction {
 public:
  BorderedResiduals(AreaProblem* p, double V0) : p_(p), V0_(V0) {
    set_num_residuals(3 * p->k() + 1);
    mutable_parameter_block_sizes()->push_back(3 * p->k());
    mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int n = 3 * p_->k();
    const Eigen::Map<const Eigen::VectorXd> y(parameters[0], n);
    const double H = parameters[1][0];
    if (!y.allFinite() || !std::isfinite(H)) return false;
    p_->set(y);
    Eigen::VectorXd g;
    p_->residual(H, &g);
    const Eigen::VectorXd gV = p_->volume_gradient();
    const double nV = gV.norm(), c = p_->base.f->volume(p_->P()) - V0_;
    if (!(nV > 0) || !g.allFinite() || !std::isfinite(c)) return false;
    Eigen::Map<Eigen::VectorXd> F(residuals, n + 1);
    F.head(n) = g;
    F(n) = c / nV;
    if (jacobians && jacobians[0]) {
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(jacobians[0], n + 1, n);
      J.topRows(n) = p_->hessian(H);
      J.row(n) = gV.transpose() / nV;
      if (!J.allFinite()) return false;
    }
    if (jacobians && jacobians[1]) {
      Eigen::Map<Eigen::VectorXd> JH(jacobians[1], n + 1);
      JH.head(n) = 2.0 * gV;
      JH(n) = 0.0;
    }
    return true;
  }

 private:
  AreaProblem* p_;
  double V0_;
};

class StopAtBorderedTolerance final : public ceres::IterationCallback {
 public:
  StopAtBorderedTolerance(AreaProblem* p, const Eigen::VectorXd* y, const double* H, double tol,
                          const std::function<double(double)>& residual)
      : p_(p), y_(y), H_(H), tol_(tol), residual_(residual) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    p_->set(*y_);
    return residual_(*H_) <= tol_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  AreaProblem* p_;
  const Eigen::VectorXd* y_;
  const double* H_;
  double tol_;
  const std::function<double(double)>& residual_;
};

}  // namespace

CorrectorStats ceres_bordered_correct(AreaProblem& p, double V0, double& H, double tol, int max_iterations,
                                      const std::function<double(double)>& residual) {
  CorrectorStats st;
  st.residual = residual(H);
  st.ok = std::isfinite(st.residual) && st.residual <= tol;
  if (st.ok || !std::isfinite(st.residual) || max_iterations <= 0) return st;
  Eigen::VectorXd buf = p.get();
  double h = H;
  ceres::Problem problem;
  problem.AddResidualBlock(new BorderedResiduals(&p, V0), nullptr, buf.data(), &h);  // owned by problem
  ceres::Solver::Options so = ceres_lm_options(max_iterations);
  so.linear_solver_type = kLinearSolver;
  // The bordered Jacobian is square and non-singular at a regular point: start as Gauss–Newton.
  so.initial_trust_region_radius = 1e12;
  so.max_trust_region_radius = 1e16;
  so.update_state_every_iteration = true;
  StopAtBorderedTolerance cb(&p, &buf, &h, tol, residual);
  so.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  p.set(buf);
  H = h;
  st.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  st.residual = residual(H);
  st.ok = std::isfinite(st.residual) && st.residual <= tol;
  return st;
}

CorrectorStats ceres_correct(CmcProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }
CorrectorStats ceres_correct(AreaProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }

}  // namespace bpde::cmc_detail
