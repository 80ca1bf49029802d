// Ceres corrector of the CMC continuation (solvers/cmc/cmc.h): Levenberg–Marquardt on the residuals
// F of triangular CMC eq. (11), with the analytic Jacobian (the exact Hessian of D_H over the free
// control points); the same for the first variation of A_H = A + 2HV (area/area_problem.h), whose
// Jacobian is the exact Hessian of A_H by quadrature. All 3k residuals over the 3k unknowns are one
// dense function, solved by ceres::TinySolver (Ceres's dense LM, header-only, so its products run
// at this library's vector width; ceres_correct_impl). The bordered V form of the area route
// (ceres_bordered_correct) is one residual block on two parameter blocks for ceres::Solve with a
// dense solver (kLinearSolver below). Ceres runs single-threaded here.
#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>
#include <ceres/tiny_solver.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "bezierpde/solvers/cmc/ceres_lm_options.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {
namespace {

// DENSE_NORMAL_CHOLESKY for the bordered V form below: the LM step from J^T J + D by a dense
// Cholesky (Eigen), a third of the flops of DENSE_QR on the augmented matrix.
constexpr ceres::LinearSolverType kLinearSolver = ceres::DENSE_NORMAL_CHOLESKY;

// The stopping test: the residual of eq. (11) as the newton corrector computes it (the exact
// denominator only when the residual may be within 1e3 x tolerance, else the last one;
// CmcProblem::evaluate), so both stop at the same test; the area problem computes it whole. F
// receives the residual vector (the free gradient) of the same evaluation.
double stop_residual(CmcProblem& p, double H, double tol, double& scale, Eigen::VectorXd& F) {
  return p.evaluate(H, F, tol, scale, &scale);
}
double stop_residual(AreaProblem& p, double H, double, double&, Eigen::VectorXd& F) { return p.residual(H, &F); }

// The two ends of a TinySolver run decided by the function (TinySolver has no callbacks): a point
// met the tolerance, or the Jacobian at an accepted point was not finite.
struct Converged {
  Eigen::VectorXd y;
  double residual;  // the stopping test's residual at y (computed whole there: it met the tolerance)
};
struct JacobianFailed {};

// The Dirichlet Gram's factor as the residuals' scale: the residuals are R = L^{-1} F by
// coordinate (R(c k + a) = (L^{-1} F_c)(a), F_c(a) = F(3a + c)), C = L L^T the Dirichlet Gram over
// the free points (D = 1/2 sum_c P_c^T C P_c), so the Jacobian is L^{-1} H. The Hessian H has the
// Bernstein conditioning of C (growing like 4^n), and the LM step solves with J^T J, which squares
// the conditioning of J: with J = H it loses the last digits that the tolerance of eq. (11) needs
// from n = 15 on (two extra steps); J^T J = H C^{-1} H has about the conditioning of H instead.
// A fixed invertible left factor leaves the roots and the Gauss–Newton step as they are. Where the
// Gram over the free points does not factor (rounding at high degree) the scale is the identity.
class GramScale {
 public:
  explicit GramScale(const CmcProblem& p) : k_(p.k()) {
    Eigen::LLT<Eigen::MatrixXd> llt(p.f->gram()(p.free, p.free));
    if (llt.info() != Eigen::Success) return;
    // L^{-1} once (k^3/3 flops), so that each Jacobian is a triangular product (Eigen's packed
    // product kernels) rather than a triangular solve.
    Linv_ = Eigen::MatrixXd::Identity(k_, k_);
    llt.matrixL().solveInPlace(Linv_);
    if (!Linv_.allFinite()) Linv_.resize(0, 0);
  }
  /// R = L^{-1} F by coordinate.
  void residuals(const Eigen::VectorXd& F, double* r) const {
    Eigen::Map<Eigen::MatrixX3d> R(r, k_, 3);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> Fc(F.data(), k_, 3);
    if (Linv_.size())
      R.noalias() = Linv_.triangularView<Eigen::Lower>() * Fc;
    else
      R = Fc;
  }
  /// J = L^{-1} H by coordinate (rows as R, columns as y), H 3k x 3k, J column-major.
  void jacobian(const Eigen::MatrixXd& H, double* j) const {
    const int n = 3 * k_;
    Eigen::Map<Eigen::MatrixXd> J(j, n, n);
    using Strided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;
    for (int c = 0; c < 3; ++c) {
      const Strided Hc(H.data() + c, k_, n, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(n, 3));
      if (Linv_.size())
        J.middleRows(c * k_, k_).noalias() = Linv_.triangularView<Eigen::Lower>() * Hc;
      else
        J.middleRows(c * k_, k_) = Hc;
    }
  }

 private:
  int k_;
  Eigen::MatrixXd Linv_;  // L^{-1}; empty: the identity scale
};

const CmcProblem& dirichlet_part(const CmcProblem& p) { return p; }
const CmcProblem& dirichlet_part(const AreaProblem& p) { return p.base; }

// The function of ceres::TinySolver: the 3k residuals of eq. (11) in the scale of GramScale over
// the 3k unknowns y, the Jacobian column-major (Eigen's default, TinySolver's layout). Every point
// evaluated gets its stopping test (on F itself) with its residuals (one evaluation); the first
// point that meets the tolerance ends the solve there (Converged), before TinySolver forms J^T J
// at it. TinySolver evaluates the residuals at a candidate point and, when it accepts the step,
// the residuals and the Jacobian at the same point again, so the residuals are reused.
template <class Problem>
class AllResiduals {
 public:
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };
  AllResiduals(Problem* p, const GramScale* s, double H, double tol) : p_(p), s_(s), H_(H), tol_(tol) {}
  int NumResiduals() const { return 3 * p_->k(); }
  int NumParameters() const { return 3 * p_->k(); }
  bool operator()(const double* parameters, double* residuals, double* jacobian) const {
    const int n = 3 * p_->k();
    const Eigen::Map<const Eigen::VectorXd> y(parameters, n);
    Eigen::Map<Eigen::VectorXd> R(residuals, n);
    // A candidate point whose residuals are not finite is a rejected step (its cost is NaN, so
    // TinySolver's gain ratio is not > 0 and the damping grows); at an accepted point (jacobian
    // asked for) the solve ends.
    if (!y.allFinite()) return fail(R, jacobian);
    if (!(last_y_.size() == n && last_y_ == y)) {
      last_y_ = y;
      p_->set(y);
      last_r_ = stop_residual(*p_, H_, tol_, scale_, F_);
      last_R_.resize(n);
      s_->residuals(F_, last_R_.data());
    }
    R = last_R_;
    if (!R.allFinite()) return fail(R, jacobian);
    if (last_r_ <= tol_) throw Converged{y, last_r_};
    if (jacobian) {
      p_->set(y);
      const Eigen::MatrixXd Hs = p_->hessian(H_);
      if (!Hs.allFinite()) throw JacobianFailed{};
      s_->jacobian(Hs, jacobian);
    }
    return true;
  }

 private:
  static bool fail(Eigen::Map<Eigen::VectorXd>& R, const double* jacobian) {
    if (jacobian) throw JacobianFailed{};
    R.setConstant(std::numeric_limits<double>::quiet_NaN());
    return false;
  }
  Problem* p_;
  const GramScale* s_;
  double H_, tol_;
  mutable Eigen::VectorXd last_y_, last_R_, F_;
  mutable double last_r_ = 0.0, scale_ = 0.0;
};

// ceres::TinySolver (Ceres's header-only Levenberg–Marquardt for small dense problems) rather than
// ceres::Solve: its normal matrix J^T J and the Cholesky of the LM system are Eigen products
// compiled with this library's flags (AVX2/AVX-512 in the native build), where ceres::Solve forms
// and factors them inside the prebuilt libceres (SSE2 in Debian's package) and allocates its
// program, evaluator and dense Jacobian on every call; measured in
// docs/performance_measurements.md, "CMC solvers (D_H)".
template <class Problem>
CorrectorStats ceres_correct_impl(Problem& p, double H, const CmcOptions& o) {
  CorrectorStats st = start_stats(p, H, o);
  if (st.ok || !std::isfinite(st.residual)) return st;
  Eigen::VectorXd y = p.get();
  const GramScale scale(dirichlet_part(p));
  const AllResiduals<Problem> f(&p, &scale, H, o.tolerance);
  ceres::TinySolver<AllResiduals<Problem>, Eigen::LLT<Eigen::MatrixXd>> solver;
  // TinySolver's loop counts from 1: at most max_corrector_iterations steps. Its own tests are set
  // out of the way (AllResiduals stops at the library's test).
  solver.options.max_num_iterations = o.max_corrector_iterations + 1;
  solver.options.gradient_tolerance = std::numeric_limits<double>::min();
  solver.options.parameter_tolerance = 0.0;
  solver.options.function_tolerance = 0.0;
  solver.options.cost_threshold = 0.0;
  // J is square and non-singular on the branch: start as Gauss–Newton (= Newton on eq. (11)).
  solver.options.initial_trust_region_radius = 1e12;
  double reached = std::numeric_limits<double>::quiet_NaN();
  try {
    solver.Solve(f, &y);  // y: TinySolver's iterate, the last accepted point when it throws
    st.iterations = std::min(solver.summary.iterations, o.max_corrector_iterations);
  } catch (const Converged& c) {
    y = c.y;
    reached = c.residual;
    st.iterations = solver.summary.iterations;  // the step that reached it is the one under way
  } catch (const JacobianFailed&) {
    st.iterations = std::max(solver.summary.iterations, 0);
  }
  p.set(y);
  st.residual = std::isnan(reached) ? p.residual(H) : reached;
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
