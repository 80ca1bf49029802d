#pragma once
// Internal to solvers/cmc/*.cpp: the trust-region subproblem of the area functional's final
// phases (area_trust_region_phase.cpp, area_soft_mode_phase.cpp), and Simpson's rule for the
// change of a function along a step from its gradients.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace bpde::cmc_detail {

/// min over ‖c‖ <= radius of the model m(c) = gb·c + ½ Σ λ_i c_i² (a quadratic model in the
/// eigenbasis V of its Hessian, gb = Vᵀg): c(μ) = −gb/(λ + μ) with μ = 0 where the Hessian is
/// positive definite and the Newton step is inside, else the μ > max(0, −λ_min) with ‖c(μ)‖ =
/// radius (bisection in log μ), and in the hard case (gb without a component along the lowest
/// mode) c completed along that mode to the boundary (Moré–Sorensen; Nocedal–Wright §4.3).
struct TrustRegionModel {
  Eigen::VectorXd lam, gb;  // eigenvalues, eigenbasis components of g
  Eigen::MatrixXd V;        // C-orthonormal eigenvectors
  // Coefficients of d(μ) in the eigenbasis.
  Eigen::VectorXd coefficients(double mu) const {
    Eigen::VectorXd c(lam.size());
    for (Eigen::Index i = 0; i < lam.size(); ++i) c(i) = -gb(i) / (lam(i) + mu);
    return c;
  }
  // The step in the eigenbasis minimising the model over ‖c‖ ≤ radius.
  Eigen::VectorXd step(double radius) const {
    Eigen::Index i0 = 0;  // the lowest mode
    const double lmin = lam.minCoeff(&i0);
    if (lmin > 0) {
      const Eigen::VectorXd c = coefficients(0.0);
      if (c.allFinite() && c.norm() <= radius) return c;
    }
    // ‖c(μ)‖ falls with μ on (max(0, −λ_min), ∞): bisection in log μ between a μ where it is above
    // the radius and one where it is below.
    const double lo0 = std::max(0.0, -lmin);
    double lo = lo0, hi = lo0 + gb.norm() / radius + std::abs(lmin) + std::numeric_limits<double>::min();
    const double tiny = lo0 > 0 ? lo0 * 1e-15 : std::numeric_limits<double>::min();
    Eigen::VectorXd near = coefficients(lo0 + tiny);
    if (!(near.allFinite() && near.norm() > radius)) {
      // The hard case: even at μ → −λ_min the step stays inside; complete it along the lowest mode.
      Eigen::VectorXd c = near.allFinite() ? near : Eigen::VectorXd::Zero(lam.size());
      c(i0) = 0;
      const double rest = radius * radius - c.squaredNorm();
      c(i0) = rest > 0 ? std::sqrt(rest) * (gb(i0) > 0 ? -1.0 : 1.0) : 0.0;
      return c;
    }
    for (int it = 0; it < 200; ++it) {
      const double mid = lo > 0 ? std::sqrt(lo * hi) : 0.5 * hi;
      if (!(mid > lo && mid < hi)) break;
      if (coefficients(mid).norm() > radius)
        lo = mid;
      else
        hi = mid;
      if (hi <= lo * (1 + 1e-12)) break;
    }
    return coefficients(hi);
  }
  // The model's predicted decrease −m(d) for eigenbasis coefficients c.
  double decrease(const Eigen::VectorXd& c) const { return -(gb.dot(c) + 0.5 * c.dot(lam.cwiseProduct(c))); }
};

/// ∫₀¹ g(y + τd)·d dτ by Simpson's rule from the gradients at y, y + d/2 and y + d: the change of
/// the function along d, accurate where its values are not (their rounding is relative to the
/// function, the gradients' to its terms).
inline double simpson_change(const Eigen::VectorXd& g0, const Eigen::VectorXd& gm, const Eigen::VectorXd& g1,
                             const Eigen::VectorXd& d) {
  return (g0.dot(d) + 4.0 * gm.dot(d) + g1.dot(d)) / 6.0;
}

}  // namespace bpde::cmc_detail
