#pragma once
// Internal to solvers/cmc/*.cpp: the CMC problem over the free control points, and the correctors.
// The free unknowns form a vector y of length 3k, y(3a + c) = P(free[a], c).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/symmetric_factor.h"
#include "energies/cmc.h"
#include "solvers/cmc/cmc.h"

namespace bpde::cmc_detail {

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
};

/// The stats of the start point of a corrector: its eq. (11) residual at H, ok when it already
/// meets the tolerance. A corrector starts iterating only when `!ok` and the residual is finite.
inline CorrectorStats start_stats(CmcProblem& p, double H, const CmcOptions& o) {
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

}  // namespace bpde::cmc_detail
