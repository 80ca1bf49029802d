#pragma once
// Internal to solvers/cmc/*.cpp: the trust-region subproblem of the area functional's final
// phase (solvers/cmc/area/soft_mode_phase.cpp, its trust-region part), and Simpson's rule for the
// change of a function along a step from its gradients.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace bpde::optim {

/// min over ‖c‖ <= radius of the model m(c) = gb·c + ½ Σ λ_i c_i² (a quadratic model in the
/// eigenbasis V of its Hessian, gb = Vᵀg): c(μ) = −gb/(λ + μ) with μ = 0 where the Hessian is
/// positive definite and the Newton step is inside, else the μ > max(0, −λ_min) with ‖c(μ)‖ =
/// radius (bisection in log(μ + λ_min)), and in the hard case (gb without a component along the
/// lowest mode, or so small a one that ‖c(μ)‖ jumps past the radius between representable μ) c
/// completed along that mode to the boundary (Moré–Sorensen; Nocedal–Wright §4.3).
struct TrustRegionModel {
  Eigen::VectorXd lam, gb;  // eigenvalues, eigenbasis components of g
  Eigen::MatrixXd V;        // orthonormal eigenvectors, the columns (the caller's coordinates)
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
    // μ = lo0 + t, t > 0: ‖c(μ)‖ falls with t. At t = thi every |λ_i + μ| >= ‖gb‖/radius, so the
    // step is inside; tiny is the smallest t that still changes μ = lo0 + t.
    const double lo0 = std::max(0.0, -lmin);
    double thi = gb.norm() / radius + std::abs(lmin) + std::numeric_limits<double>::min();
    const double tiny = std::max(lo0 * 4 * std::numeric_limits<double>::epsilon(), std::numeric_limits<double>::min());
    const Eigen::VectorXd near = coefficients(lo0 + tiny);
    if (lmin <= 0 && near.allFinite() && near.norm() <= radius) {
      // The hard case: even at μ → −λ_min the step stays inside (gb has no component along the
      // lowest mode): go along that mode to the boundary, downhill.
      Eigen::VectorXd c = near;
      for (Eigen::Index i = 0; i < c.size(); ++i)
        if (lam(i) + lo0 <= tiny) c(i) = 0;
      const double rest = radius * radius - c.squaredNorm();
      c(i0) = rest > 0 ? std::sqrt(rest) * (gb(i0) > 0 ? -1.0 : 1.0) : 0.0;
      return c;
    }
    // Bisection in log t between tlo (outside, or not finite) and thi (inside), to the radius.
    double tlo = tiny;
    for (int it = 0; it < 300; ++it) {
      const double mid = std::sqrt(tlo * thi);
      if (!(mid > tlo && mid < thi)) break;
      const Eigen::VectorXd c = coefficients(lo0 + mid);
      if (!c.allFinite() || c.norm() > radius)
        tlo = mid;
      else
        thi = mid;
      if (std::abs(coefficients(lo0 + thi).norm() - radius) <= 1e-12 * radius) break;
    }
    Eigen::VectorXd c = coefficients(lo0 + thi);
    // Nearly the hard case (gb's component along the lowest mode tiny, so that ‖c‖ jumps past the
    // radius between representable μ): go on along the lowest mode to the boundary.
    if (lmin < 0 && c.norm() < radius) {
      const double rest = radius * radius - (c.squaredNorm() - c(i0) * c(i0));
      if (rest > 0) c(i0) = std::sqrt(rest) * (gb(i0) > 0 ? -1.0 : 1.0);
    }
    return c;
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

}  // namespace bpde::optim
