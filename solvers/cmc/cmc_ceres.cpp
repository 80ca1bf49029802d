// Ceres corrector of the CMC continuation (solvers/cmc/cmc.h): Levenberg–Marquardt on the residuals
// F_I of triangular CMC eq. (11), one residual block per free control point, with analytic Jacobians
// (the 3x3 blocks of the exact Hessian of D_H). The blocks share one evaluation of F and of the
// Hessian per parameter vector (Ceres runs single-threaded here).
#include <ceres/ceres.h>

#include <cmath>
#include <memory>

#include "solvers/cmc/cmc_area_problem.h"
#include "solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {
namespace {

template <class Problem>
struct SharedEvaluation {
  Problem* p = nullptr;
  double H = 0.0;
  Eigen::VectorXd y, F;
  Eigen::MatrixXd J;
  bool has_F = false, has_J = false, F_ok = false, J_ok = false;

  bool ensure(double const* const* params, bool need_J) {
    const int k = p->k();
    Eigen::VectorXd yn(3 * k);
    for (int a = 0; a < k; ++a)
      for (int c = 0; c < 3; ++c) yn(3 * a + c) = params[a][c];
    if (!yn.allFinite()) return false;
    if (!has_F || yn != y) {
      y = yn;
      p->set(y);
      F = p->gradient(H);
      F_ok = F.allFinite();
      has_F = true;
      has_J = false;
    }
    if (need_J && !has_J) {
      p->set(y);
      J = p->hessian(H);
      J_ok = J.allFinite();
      has_J = true;
    }
    return F_ok && (!need_J || J_ok);
  }
};

template <class Problem>
class PointResidual final : public ceres::CostFunction {
 public:
  PointResidual(SharedEvaluation<Problem>* e, int a) : e_(e), a_(a) {
    set_num_residuals(3);
    for (int b = 0; b < e->p->k(); ++b) mutable_parameter_block_sizes()->push_back(3);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!e_->ensure(parameters, jacobians != nullptr)) return false;
    for (int r = 0; r < 3; ++r) residuals[r] = e_->F(3 * a_ + r);
    if (jacobians) {
      const int k = e_->p->k();
      for (int b = 0; b < k; ++b) {
        if (!jacobians[b]) continue;
        for (int r = 0; r < 3; ++r)
          for (int s = 0; s < 3; ++s) jacobians[b][3 * r + s] = e_->J(3 * a_ + r, 3 * b + s);
      }
    }
    return true;
  }

 private:
  SharedEvaluation<Problem>* e_;
  int a_;
};

template <class Problem>
class StopAtTolerance final : public ceres::IterationCallback {
 public:
  StopAtTolerance(Problem* p, const Eigen::VectorXd* buf, double H, double tol)
      : p_(p), buf_(buf), H_(H), tol_(tol) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    p_->set(*buf_);
    const double r = p_->residual(H_);
    return r <= tol_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  Problem* p_;
  const Eigen::VectorXd* buf_;
  double H_, tol_;
};

template <class Problem>
CorrectorStats ceres_correct_impl(Problem& p, double H, const CmcOptions& o) {
  CorrectorStats st;
  st.residual = p.residual(H);
  st.ok = st.residual <= o.tolerance;
  if (st.ok || !std::isfinite(st.residual)) return st;
  const int k = p.k();
  Eigen::VectorXd buf = p.get();
  SharedEvaluation<Problem> eval;
  eval.p = &p;
  eval.H = H;
  ceres::Problem::Options po;
  ceres::Problem problem(po);
  std::vector<double*> blocks(static_cast<size_t>(k));
  for (int b = 0; b < k; ++b) blocks[static_cast<size_t>(b)] = buf.data() + 3 * b;
  for (int a = 0; a < k; ++a) problem.AddResidualBlock(new PointResidual<Problem>(&eval, a), nullptr, blocks);

  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;  // J^T J would square the Bernstein conditioning
  so.max_num_iterations = o.max_corrector_iterations;
  // J is square and non-singular on the branch: start as Gauss–Newton (= Newton on eq. (11)).
  so.initial_trust_region_radius = 1e12;
  so.max_trust_region_radius = 1e16;
  so.function_tolerance = 1e-30;
  so.gradient_tolerance = 1e-30;
  so.parameter_tolerance = 1e-30;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.update_state_every_iteration = true;
  StopAtTolerance<Problem> cb(&p, &buf, H, o.tolerance);
  so.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  p.set(buf);
  st.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  st.residual = p.residual(H);
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  return st;
}

}  // namespace

CorrectorStats ceres_correct(CmcProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }
CorrectorStats ceres_correct(AreaProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }

}  // namespace bpde::cmc_detail
