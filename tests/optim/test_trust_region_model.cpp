// solvers/optim/trust_region_model.h: the trust-region subproblem of the area functional's final
// phase against its optimality conditions (Moré–Sorensen: (K + μ I) c = −g, μ >= 0, K + μ I
// positive semidefinite, μ (radius − ‖c‖) = 0) and against brute force over the sphere ‖c‖ = radius,
// and Simpson's rule for the change of a function along a step against exact polynomials.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "bezierpde/solvers/optim/trust_region_model.h"

namespace {

using bpde::optim::simpson_change;
using bpde::optim::TrustRegionModel;

TrustRegionModel model(const Eigen::VectorXd& lam, const Eigen::VectorXd& g) {
  return {lam, g, Eigen::MatrixXd::Identity(lam.size(), lam.size())};
}

// The model's value at c (the eigenbasis is the identity here).
double value(const TrustRegionModel& m, const Eigen::VectorXd& c) { return -m.decrease(c); }

// The multiplier μ of the step c: (λ_i + μ) c_i = −g_i in every component where c_i is not 0.
double multiplier(const TrustRegionModel& m, const Eigen::VectorXd& c) {
  Eigen::Index i = 0;
  c.cwiseAbs().maxCoeff(&i);
  return -m.gb(i) / c(i) - m.lam(i);
}

TEST(TrustRegionModel, NewtonStepInsideTheRegion) {
  const TrustRegionModel m = model(Eigen::Vector3d(1, 2, 4), Eigen::Vector3d(-1, 2, -4));
  const Eigen::VectorXd c = m.step(10.0);
  EXPECT_LT((c - Eigen::Vector3d(1, -1, 1)).norm(), 1e-15);
  EXPECT_NEAR(m.decrease(c), 0.5 * (1 + 2 + 4), 1e-14);  // −m(c) = ½ gᵀK⁻¹g
}

// Positive definite but the Newton step is outside; indefinite: on the boundary, with μ >= −λ_min
// and every component solving (λ_i + μ) c_i = −g_i, and no point of the circle lower.
TEST(TrustRegionModel, BoundaryStepMeetsTheOptimalityConditions) {
  for (const Eigen::Vector2d& lam : {Eigen::Vector2d(1, 3), Eigen::Vector2d(-2, 1), Eigen::Vector2d(-1, -0.5)}) {
    const TrustRegionModel m = model(lam, Eigen::Vector2d(0.7, -1.3));
    const double radius = 0.4;
    const Eigen::VectorXd c = m.step(radius);
    EXPECT_NEAR(c.norm(), radius, 1e-12 * radius) << lam.transpose();
    const double mu = multiplier(m, c);
    EXPECT_GE(mu, std::max(0.0, -lam.minCoeff())) << lam.transpose();
    for (int i = 0; i < 2; ++i) EXPECT_NEAR((lam(i) + mu) * c(i), -m.gb(i), 1e-9) << lam.transpose();
    double best = INFINITY;
    for (int k = 0; k < 20000; ++k) {
      const double t = 2 * std::numbers::pi * k / 20000;
      best = std::min(best, value(m, Eigen::Vector2d(radius * std::cos(t), radius * std::sin(t))));
    }
    EXPECT_LE(value(m, c), best + 1e-9) << lam.transpose();
    EXPECT_GT(m.decrease(c), 0) << lam.transpose();
  }
}

// The hard case: no gradient along the lowest (negative) mode, and even at μ → −λ_min the step
// stays inside: the step goes to the boundary along that mode, where the model is lowest.
TEST(TrustRegionModel, HardCaseGoesAlongTheLowestMode) {
  const TrustRegionModel m = model(Eigen::Vector2d(-1, 2), Eigen::Vector2d(0, 0.3));
  const double radius = 1.0;
  const Eigen::VectorXd c = m.step(radius);
  EXPECT_NEAR(c.norm(), radius, 1e-12);
  EXPECT_NEAR(c(1), -0.3 / (2 - (-1)), 1e-9);  // μ = −λ_min = 1: c_1 = −g_1 / (λ_1 + 1)
  EXPECT_NEAR(std::abs(c(0)), std::sqrt(1 - c(1) * c(1)), 1e-9);
  double best = INFINITY;
  for (int k = 0; k < 20000; ++k) {
    const double t = 2 * std::numbers::pi * k / 20000;
    best = std::min(best, value(m, Eigen::Vector2d(std::cos(t), std::sin(t))));
  }
  EXPECT_LE(value(m, c), best + 1e-9);
}

// The minimum of the model over the circle ‖c‖ = radius by brute force (two dimensions).
double circle_minimum(const TrustRegionModel& m, double radius) {
  double best = INFINITY;
  for (int k = 0; k < 200000; ++k) {
    const double t = 2 * std::numbers::pi * k / 200000;
    best = std::min(best, value(m, Eigen::Vector2d(radius * std::cos(t), radius * std::sin(t))));
  }
  return best;
}

// Nearly the hard case (gb along the lowest mode 1e-14, far below what μ can resolve next to
// −λ_min), an eigenvalue so small that c(μ) overflows next to it, and λ_min = 0 with g = 0: the
// step is on the boundary (or, with g = 0 and nothing to gain, any feasible point) and no point of
// the circle is lower. (The bisection in log μ stopped 1e-12 of μ short of −λ_min in the first
// case and returned a step of length 0.1 inside the region; the second took the hard case.)
TEST(TrustRegionModel, NearlyHardAndDegenerateCases) {
  for (const auto& [lam, g] : {std::pair{Eigen::Vector2d(-1, 2), Eigen::Vector2d(1e-14, 0.3)},
                               std::pair{Eigen::Vector2d(-1e-300, 1), Eigen::Vector2d(0.3, 0.1)},
                               std::pair{Eigen::Vector2d(-1, 2), Eigen::Vector2d(-1e-9, 0.3)}}) {
    const TrustRegionModel m = model(lam, g);
    const Eigen::VectorXd c = m.step(1.0);
    ASSERT_TRUE(c.allFinite()) << lam.transpose();
    EXPECT_NEAR(c.norm(), 1.0, 1e-9) << lam.transpose() << " / " << g.transpose();
    EXPECT_LE(value(m, c), circle_minimum(m, 1.0) + 1e-9) << lam.transpose() << " / " << g.transpose();
  }
  const TrustRegionModel flat = model(Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 0));
  const Eigen::VectorXd c = flat.step(0.5);
  ASSERT_TRUE(c.allFinite());
  EXPECT_LE(c.norm(), 0.5 * (1 + 1e-12));
  EXPECT_EQ(flat.decrease(c), 0.0);  // nothing to gain: the caller stops (its pred > 0 test)
}

// Simpson's rule integrates the gradient along the step, a polynomial in τ of one degree less
// than f: exact for f of degree <= 4, and for f = Σ y_i⁵ its error is exactly (1/2880) times the
// fourth τ-derivative of the integrand, 120 Σ d_i⁵ (a wrong weight, e.g. the trapezoid rule,
// misses the quartic by far more than that).
TEST(TrustRegionModel, SimpsonChangeIsExactToDegreeFour) {
  const Eigen::Vector3d a(0.3, -1.1, 0.7), b(2.0, 0.5, -0.4), y(0.2, -0.6, 1.3), d(0.05, 0.11, -0.07);
  auto f = [&](const Eigen::Vector3d& x) {
    return (a.array() * x.array().pow(4) + b.array() * x.array().cube() + x.array().square()).sum();
  };
  auto g = [&](const Eigen::Vector3d& x) {
    return Eigen::VectorXd(4 * a.array() * x.array().cube() + 3 * b.array() * x.array().square() + 2 * x.array());
  };
  const double exact = f(y + d) - f(y);
  EXPECT_NEAR(simpson_change(g(y), g(y + 0.5 * d), g(y + d), d), exact, 1e-14);
  const double trapezoid = 0.5 * (g(y) + g(y + d)).dot(d);
  EXPECT_GT(std::abs(trapezoid - exact), 1e-6);
  auto g5 = [](const Eigen::Vector3d& x) { return Eigen::VectorXd(5 * x.array().pow(4)); };
  const double exact5 = ((y + d).array().pow(5) - y.array().pow(5)).sum();
  const double err = simpson_change(g5(y), g5(y + 0.5 * d), g5(y + d), d) - exact5;
  EXPECT_NEAR(err, 120.0 / 2880.0 * d.array().pow(5).sum(), 1e-14);
}

}  // namespace
