// Ceres corrector of the CMC continuation (solvers/cmc/cmc.h): Levenberg–Marquardt on the residuals
// F of triangular CMC eq. (11), with the analytic Jacobian (the exact Hessian of D_H over the free
// control points); the same for the first variation of A_H = A + 2HV (cmc_area_problem.h), whose
// Jacobian is the exact Hessian of A_H by quadrature.
//
// The LM is ceres::TinySolver (ceres/tiny_solver.h): dense Eigen, all 3k residuals and the 3k
// unknowns as one dense Jacobian, the step from J^T J + D by a dense Cholesky. It replaces
// ceres::Solve with one residual block and DENSE_NORMAL_CHOLESKY, whose own machinery (the
// program evaluation, the block-sparse copies, the Jacobi scaling and the trust-region bookkeeping)
// cost more than the dense algebra itself (docs/performance.md, "The Ceres CMC route", 4c).
#include <ceres/tiny_solver.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "bezierpde/solvers/cmc/cmc_area_problem.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"

namespace bpde::cmc_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The LM step's solver for TinySolver: the Cholesky of J^T J + D (SPD for any D > 0; Eigen's blocked
// LLT, cheaper than TinySolver's default unblocked LDLT). When the factorisation fails the step is
// NaN, which the functor evaluates as a NaN residual, so TinySolver rejects it and raises the
// damping.
class LltStep {
 public:
  void compute(const Eigen::MatrixXd& A) { llt_.compute(A); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    if (llt_.info() != Eigen::Success) return Eigen::VectorXd::Constant(b.size(), kNaN);
    return llt_.solve(b);
  }

 private:
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

// The stopping test: the residual of eq. (11) as the newton corrector computes it (the exact
// denominator only when the residual may be within 1e3 x tolerance, else the last one;
// CmcProblem::evaluate), so both stop at the same test; the area problem computes it whole. F
// receives the residual vector (the free gradient) of the same evaluation.
double stop_residual(CmcProblem& p, double H, double tol, double& scale, Eigen::VectorXd& F) {
  return p.evaluate(H, F, tol, scale, &scale);
}
double stop_residual(AreaProblem& p, double H, double, double&, Eigen::VectorXd& F) { return p.residual(H, &F); }

// Thrown by the functor to end TinySolver (which has no callback): at a point that meets the
// tolerance, or when the Hessian is not finite.
struct Stop {};

// TinySolver's functor: residuals F = the free gradient, Jacobian = the exact Hessian. Every new
// point is tested by stop_residual (that evaluation gives F too), as the newton corrector tests
// each iterate; TinySolver asks for the Jacobian at an accepted point after evaluating F there,
// and the F of that point is reused.
template <class Problem>
class AllResiduals {
 public:
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };

  AllResiduals(Problem* p, double H, double tol) : p_(p), H_(H), tol_(tol), n_(3 * p->k()) {}
  int NumResiduals() const { return n_; }
  int NumParameters() const { return n_; }

  bool operator()(const double* x, double* residuals, double* jacobian) const {
    const Eigen::Map<const Eigen::VectorXd> y(x, n_);
    Eigen::Map<Eigen::VectorXd> F(residuals, n_);
    if (!jacobian) ++steps_;  // TinySolver evaluates a candidate step without the Jacobian
    if (!(last_y_.size() == n_ && last_y_ == y)) {
      if (!y.allFinite()) {
        F.setConstant(kNaN);
        return false;
      }
      p_->set(y);
      last_y_ = y;
      const double r = stop_residual(*p_, H_, tol_, scale_, last_F_);
      if (r <= tol_) {
        converged_ = true;
        throw Stop{};
      }
    }
    F = last_F_;
    if (!F.allFinite()) return false;
    if (jacobian) {
      Eigen::Map<Eigen::MatrixXd> J(jacobian, n_, n_);  // column-major (TinySolver's layout)
      J = p_->hessian(H_);
      if (!J.allFinite()) throw Stop{};
    }
    return true;
  }

  int steps() const { return steps_; }
  bool converged() const { return converged_; }
  const Eigen::VectorXd& last_point() const { return last_y_; }

 private:
  Problem* p_;
  double H_, tol_;
  int n_;
  mutable Eigen::VectorXd last_y_, last_F_;
  mutable double scale_ = 0.0;
  mutable int steps_ = 0;
  mutable bool converged_ = false;
};

template <class Problem>
CorrectorStats ceres_correct_impl(Problem& p, double H, const CmcOptions& o) {
  CorrectorStats st = start_stats(p, H, o);
  if (st.ok || !std::isfinite(st.residual)) return st;
  Eigen::VectorXd x = p.get();
  const AllResiduals<Problem> f(&p, H, o.tolerance);
  ceres::TinySolver<AllResiduals<Problem>, LltStep> solver;
  // TinySolver takes at most max_num_iterations - 1 steps.
  solver.options.max_num_iterations = o.max_corrector_iterations + 1;
  // J is square and non-singular on the branch: start as Gauss–Newton (= Newton on eq. (11)).
  solver.options.initial_trust_region_radius = 1e12;
  // Only the eq. (11) test of the functor ends the iteration (TinySolver's tests are strict "<").
  solver.options.gradient_tolerance = 0.0;
  solver.options.parameter_tolerance = 0.0;
  solver.options.function_tolerance = 0.0;
  solver.options.cost_threshold = 0.0;
  try {
    solver.Solve(f, &x);
  } catch (const Stop&) {
  }
  // The point tested last meets the tolerance; otherwise TinySolver's x is its last accepted point.
  p.set(f.converged() ? f.last_point() : x);
  st.iterations = f.steps();
  st.residual = p.residual(H);
  st.ok = std::isfinite(st.residual) && st.residual <= o.tolerance;
  return st;
}

}  // namespace

CorrectorStats ceres_correct(CmcProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }
CorrectorStats ceres_correct(AreaProblem& p, double H, const CmcOptions& o) { return ceres_correct_impl(p, H, o); }

}  // namespace bpde::cmc_detail
