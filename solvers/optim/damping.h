#pragma once
// The damping policy of a regularised Newton corrector: the step solves (K + θ r C) δ = −g (K the
// Hessian, C a positive definite metric, r the relative residual), and θ moves with how well the
// last step went (compare the trust-radius update of ceres' trust_region_minimizer.cc). One
// policy object per corrector, so that the constants of every damping loop are in one place and
// each loop is "try, then accepted()/rejected()".
#include <algorithm>

namespace bpde::optim {

struct Damping {
  int max_tries = 20;    ///< factorisations per iteration before the iteration gives up
  double floor = 1e-8;   ///< θ never falls below this after a good step
  double shrink = 4.0;   ///< θ /= shrink after a good step (gain ratio above `good_ratio`)
  double grow = 4.0;     ///< θ *= grow after a poor one (gain ratio below `poor_ratio`)
  double reject = 10.0;  ///< θ *= reject after a rejected step or a failed factorisation
  double accept_ratio = 0.1;  ///< a step whose gain ratio exceeds this is accepted
  double good_ratio = 0.75;
  double poor_ratio = 0.25;
  /// A rejection raises θ from at least `floor` (a θ of 0 would otherwise stay 0).
  bool reject_from_floor = false;

  /// θ after an accepted step with gain ratio rho (actual over predicted change of the merit).
  void accepted(double& theta, double rho) const {
    if (rho > good_ratio) good(theta);
    if (rho < poor_ratio) theta *= grow;
  }
  /// θ after a step judged good without a gain ratio (a corrector that accepts on a falling residual).
  void good(double& theta) const { theta = std::max(theta / shrink, floor); }
  /// θ after a rejected step or a factorisation that failed.
  void rejected(double& theta) const { theta = (reject_from_floor ? std::max(theta, floor) : theta) * reject; }
};

}  // namespace bpde::optim
