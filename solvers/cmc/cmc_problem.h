#pragma once
// Internal to solvers/cmc/*.cpp: the CMC problem over the free control points, and the correctors.
// The free unknowns form a vector y of length 3k, y(3a + c) = P(free[a], c).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/symmetric_factor.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/area/sparse_terms.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {
class ComplexNet;  // solvers/cmc/complex_net.h
struct PatchComplex;
}

namespace bpde::cmc_detail {

/// x in a solver message: %g with `digits` significant digits, and 0 for -0.
inline std::string num(double x, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x == 0.0 ? 0.0 : x);
  return buf;
}

struct CmcProblem {
  std::shared_ptr<const CmcFunctional> f;
  std::vector<int> free;
  Eigen::MatrixX3d P;  // all points; rows not in `free` hold the data

  int k() const { return static_cast<int>(free.size()); }
  Eigen::VectorXd get() const;
  void set(const Eigen::VectorXd& y);
  /// Free rows of ∇D_H as a 3k vector.
  Eigen::VectorXd gradient(double H) const;
  /// Free rows of ∇V as a 3k vector.
  Eigen::VectorXd volume_gradient() const;
  Eigen::MatrixXd hessian(double H) const { return f->hessian(P, H, free); }
  double residual(double H) const { return f->residual(P, H, free); }
  /// Residual, and the free gradient into g. With scale_hint > 0 (the residual's denominator at
  /// a nearby point) the exact denominator is computed only when the residual may be within
  /// 1e3 x tolerance; otherwise |F|/scale_hint is returned. scale receives the denominator used.
  double evaluate(double H, Eigen::VectorXd& g, double tolerance = 0.0, double scale_hint = 0.0,
                  double* scale = nullptr) const;
  double value(double H) const { return f->value(P, H); }
};

/// Cholesky, else pivoted LDL^T with every pivot >= -1e-10 max|pivot| counted as positive
/// (core/symmetric_factor.h).
using SymFactor = SymmetricFactor<double>;

/// Outcome of one corrector run at fixed H, starting from problem.P.
struct CorrectorStats {
  bool ok = false;  ///< residual <= tolerance
  int iterations = 0;
  double residual = 0.0;
  int pd = -1;           ///< 1/0: Hessian at the solution (positive definite / not); -1 unknown
  int polish_steps = 0;  ///< Newton steps added after NLopt
  /// Area soft-mode phase: it stopped because no step lowers the reduced first variation (a
  /// stationary point of its norm over the soft modes, not a critical point of A_H).
  bool soft_stationary = false;
  int soft_iterations = 0;  ///< of `iterations`, those of the area soft-mode phase
  int trust_region_iterations = 0;  ///< of `soft_iterations`, those of its trust-region part
  /// The trust-region part ended above the tolerance after a step refused by its regularity bound
  /// (its descent heads for a degenerate parametrisation).
  bool trust_region_blocked = false;
};

/// The stats of the start point of a corrector: its eq. (11) residual at H, ok when it already
/// meets the tolerance. A corrector starts iterating only when `!ok` and the residual is finite.
template <class Problem>  // CmcProblem or AreaProblem (area/area_problem.h)
CorrectorStats start_stats(Problem& p, double H, const CmcOptions& o) {
  CorrectorStats st;
  st.residual = p.residual(H);
  st.ok = st.residual <= o.tolerance;
  return st;
}

/// Newton with the exact Hessian.
CorrectorStats newton_correct(CmcProblem& p, double H, const CmcOptions& o, int max_iterations);
/// Ceres LM on the residual blocks of eq. (11).
CorrectorStats ceres_correct(CmcProblem& p, double H, const CmcOptions& o);
/// NLopt LD_LBFGS on D_H (preconditioned by the Cholesky factor L of the free Gram), then polish.
CorrectorStats nlopt_correct(CmcProblem& p, double H, const CmcOptions& o, const Eigen::MatrixXd& L);

/// V mode: minimise D subject to V = V0 from problem.P (the Dirichlet extremal) with SLSQP, then a
/// bordered Newton polish. On return H holds the multiplier.
CorrectorStats nlopt_volume_solve(CmcProblem& p, double V0, const CmcOptions& o, const Eigen::MatrixXd& L, double& H,
                                  std::string& note);

/// H = -<∇D,∇V>/(2|∇V|^2) over the free points (0 if ∇V = 0).
double multiplier(const CmcProblem& p);


// ---- shared by the D_H and the A_H routes (cmc.cpp, area/)

std::string fold_message(double h, bool gram_singular);
void check_degree(const TriangularNet& net, FixedSet fixed);
void check_degree(const TensorNet& net, FixedSet fixed);
void check_degree(const ComplexNet& net, FixedSet fixed);
std::shared_ptr<const CmcFunctional> functional_for(const TriangularNet& net);
std::shared_ptr<const CmcFunctional> functional_for(const TensorNet& net);
std::shared_ptr<const CmcFunctional> functional_for(const ComplexNet& net);
TriangularNet make_net(const TriangularNet& data, const Eigen::MatrixX3d& P);
TensorNet make_net(const TensorNet& data, const Eigen::MatrixX3d& P);
ComplexNet make_net(const ComplexNet& data, const Eigen::MatrixX3d& P);

// Dirichlet extremal into p.P (Cholesky, or pivoted LDL^T when rounding makes the Bernstein Gram
// indefinite). Returns the factor used for the tangent at H = 0 and a Cholesky factor L of the
// (if needed slightly shifted) free Gram for the NLopt preconditioner.
//
// A complex with more than area_impl::kSparseFromCoordinates free coordinates (area/tuning.h) starts sparse
// (dirichlet_solve_sparse): the free Gram is the sparse Gram of the complex (solvers/complex/
// complex_extremal.h: complex_gram, the patches' Grams summed), factored by SparseSymFactor
// (CHOLMOD; LDL^T where the Cholesky factor fails); `gram` is then null and `sparse` holds the
// factor, and L is formed (dense) only when a route asks for it (preconditioner()).
struct DirichletFactor {
  std::unique_ptr<SymFactor> gram;
  std::shared_ptr<const SparseSymFactor> sparse;
  Eigen::MatrixXd L;

  /// Cholesky factor of the free Gram (the test of a singular Gram).
  bool cholesky() const { return sparse ? sparse->cholesky() : gram->cholesky(); }
  /// C_ff^{-1} B (k x 3) by the factor held.
  Eigen::MatrixX3d solve(const Eigen::MatrixX3d& B) const;
};

DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx);
/// The sparse start of a complex (above); p.f is the complex's assembled D_H and `c` the complex
/// (its points are not read: the fixed rows come from p.P). Falls back to dirichlet_solve when
/// neither sparse factor succeeds.
DirichletFactor dirichlet_solve_sparse(CmcProblem& p, const std::vector<int>& fixed_idx, const PatchComplex& c);
/// The start of each net type: a complex above kSparseFromCoordinates free coordinates sparse.
DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx, const ComplexNet& net);
inline DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx, const TriangularNet&) {
  return dirichlet_solve(p, fixed_idx);
}
inline DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx, const TensorNet&) {
  return dirichlet_solve(p, fixed_idx);
}
/// The NLopt preconditioner L of `f` (formed from p's dense free Gram on first use after a
/// sparse start).
const Eigen::MatrixXd& preconditioner(DirichletFactor& f, const CmcProblem& p);

/// The common start of the D_H and the A_H solves: the options and the degree checked, the problem
/// on the free points of `data` (fixed rows checked finite, free rows zeroed) with the Dirichlet
/// extremal in P, the fixed rows and the Dirichlet factor.
struct DirichletStart {
  CmcProblem p;
  std::vector<int> fixed_idx;
  DirichletFactor dir;
};

template <class Net>
DirichletStart dirichlet_start(const Net& data, const CmcOptions& o) {
  o.validate();
  check_degree(data, o.fixed);
  DirichletStart s{CmcProblem{functional_for(data), data.free_indices(o.fixed), data.points()},
                   data.fixed_indices(o.fixed), {}};
  require_finite_rows(s.p.P, s.fixed_idx, "cmc");
  for (int r : s.p.free) s.p.P.row(r).setZero();
  s.dir = dirichlet_solve(s.p, s.fixed_idx, data);
  return s;
}

/// The order of the branch's Taylor series that predicts each continuation step (cmc.cpp).
constexpr int kBranchSeriesOrder = 4;
/// The coefficients m = 1 … kBranchSeriesOrder of the branch P(H0 + s) = Σ_m P_m s^m through the
/// critical point p.P at H0 (free rows, 3k vectors): K P_m = -2 (H0 S'_m + S_{m-1}) from the
/// quadratic ∇V (cmc.cpp); g0 = ∇V at p.P (free rows), solve_K solves with the Hessian K of D_H
/// there (the Dirichlet Gram at H0 = 0). Fewer where a solve is not finite.
std::vector<Eigen::VectorXd> branch_series(const CmcProblem& p, double H0, const Eigen::VectorXd& g0,
                                           const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& solve_K);
/// y + Σ_m series[m-1] s^m over the terms while their size falls.
Eigen::VectorXd branch_prediction(const Eigen::VectorXd& y, const std::vector<Eigen::VectorXd>& series, double s);

/// First step: the whole way to Ht, but not beyond |H| = 16 / (size of the fixed data).
double first_step(double Ht, const Eigen::MatrixX3d& P, const std::vector<int>& fixed_idx);
/// The corrector moved the prediction pred (from y) to yn by at most half the step.
bool on_branch(const Eigen::VectorXd& y, const Eigen::VectorXd& pred, const Eigen::VectorXd& yn);

// The step control of the continuation in H (cmc.h): proposes the next H on the way from 0 to the
// target; an accepted step doubles the next one after an easy corrector run (<= 4 iterations unless
// told otherwise) and keeps it otherwise; a rejected step halves it, until it falls below min_step relative to
// max(1, |H reached|) (the fold). At most max_continuation_steps attempts.
class StepController {
 public:
  struct Step {
    double s;   ///< the step in H
    double hn;  ///< the H proposed: h + s, exactly the target on the last step
  };
  StepController(double target, double first_step, const CmcOptions& o)
      : target_(target), step_(first_step), min_step_(o.min_step), max_attempts_(o.max_continuation_steps) {}

  bool reached_target() const { return h_ == target_; }
  /// The last H accepted.
  double h() const { return h_; }
  /// Counts an attempt; false once max_continuation_steps attempts are used up.
  bool attempt() { return ++attempts_ <= max_attempts_; }
  Step propose() const {
    double s = step_;
    if (std::abs(target_ - h_) <= std::abs(s) * (1 + 1e-12)) s = target_ - h_;
    return {s, (target_ - h_ == s) ? target_ : h_ + s};
  }
  /// An easy step (a corrector run of at most `easy` iterations) doubles the next one.
  void accept(const Step& st, int corrector_iterations, int easy = 4) {
    h_ = st.hn;
    step_ = corrector_iterations <= easy ? 2 * st.s : st.s;
  }
  /// Halves the step; false when it collapsed (a fold at h()).
  bool reject(const Step& st) {
    step_ = st.s / 2;
    return !(std::abs(step_) < min_step_ * std::max(1.0, std::abs(h_)));
  }

 private:
  double target_, step_, min_step_;
  int max_attempts_, attempts_ = 0;
  double h_ = 0.0;
};

/// The area functional (cmc.h, "The area functional"; area/driver.cpp). options are validated.
CmcResult<TriangularNet> solve_area(const TriangularNet& data, const CmcOptions& options);
CmcResult<TensorNet> solve_area(const TensorNet& data, const CmcOptions& options);
CmcResult<ComplexNet> solve_area(const ComplexNet& data, const CmcOptions& options);

}  // namespace bpde::cmc_detail
