// Levenberg–Marquardt with geodesic acceleration (solvers/optim/levenberg_marquardt.h) on problems
// with closed-form answers: the second directional derivative on quadratic residuals, the
// accelerated step as Chebyshev's third-order step in one unknown, the Rosenbrock valley, the
// nearest point of a sphere (the constrained step), and bad input.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/optim/levenberg_marquardt.h"

namespace bpde::optim {
namespace {

// r(x) = (x0² + 3x0x1 − x2, x1² − 2x2x0 + 1, 5x2²): quadratic, so its second directional
// derivative along d is exactly dᵀ∇²r_i d = (2d0² + 6d0d1, 2d1² − 4d0d2, 10d2²).
Eigen::VectorXd quadratic_r(const Eigen::VectorXd& x) {
  return Eigen::Vector3d(x(0) * x(0) + 3 * x(0) * x(1) - x(2), x(1) * x(1) - 2 * x(2) * x(0) + 1, 5 * x(2) * x(2));
}
Eigen::MatrixXd quadratic_J(const Eigen::VectorXd& x) {
  Eigen::Matrix3d J;
  J << 2 * x(0) + 3 * x(1), 3 * x(0), -1,  //
      -2 * x(2), 2 * x(1), -2 * x(0),      //
      0, 0, 10 * x(2);
  return J;
}

TEST(LevenbergMarquardt, SecondDirectionalDerivativeIsExactForQuadraticResiduals) {
  const Eigen::Vector3d x(0.3, -1.1, 0.7), d(0.25, 0.5, -0.4);
  const Eigen::Vector3d exact(2 * d(0) * d(0) + 6 * d(0) * d(1), 2 * d(1) * d(1) - 4 * d(0) * d(2), 10 * d(2) * d(2));
  for (double h : {0.1, 0.02, 0.7}) {
    const Eigen::VectorXd got =
        second_directional_derivative(quadratic_r(x), quadratic_r(x + h * d), quadratic_J(x), d, h);
    EXPECT_LT((got - exact).norm(), 1e-12 * exact.norm()) << "h = " << h;
  }
}

// One residual in one unknown: r(x) = x² − 2.
LeastSquaresProblem square_root_of_two() {
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = Eigen::VectorXd::Constant(1, x(0) * x(0) - 2);
    if (J) *J = Eigen::MatrixXd::Constant(1, 1, 2 * x(0));
  };
  return p;
}

// With λ = 0 the velocity is Newton's step −r/r' and the accelerated step δ + a/2 is Chebyshev's
// x − r/r' − r''r²/(2r'³); with a in place of a/2 (or no acceleration) the iterates differ from
// Chebyshev's by far more than rounding.
TEST(LevenbergMarquardt, AcceleratedStepIsChebyshevsThirdOrderStep) {
  const LeastSquaresProblem p = square_root_of_two();
  LevenbergMarquardtOptions o;
  o.initial_lambda = 0;
  double cheb = 1.5, newton = 1.5;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 1.5), xn = x;
  for (int k = 1; k <= 3; ++k) {
    const double r = cheb * cheb - 2, dr = 2 * cheb;
    cheb = cheb - r / dr - 2 * r * r / (2 * dr * dr * dr);
    newton = newton - (newton * newton - 2) / (2 * newton);
    o.max_iterations = k;
    x = Eigen::VectorXd::Constant(1, 1.5);
    o.geodesic_acceleration = true;
    const LsOutcome out = levenberg_marquardt(p, x, o);
    EXPECT_EQ(out.iterations, k);
    EXPECT_NEAR(x(0), cheb, 1e-14) << "iteration " << k;
    xn = Eigen::VectorXd::Constant(1, 1.5);
    o.geodesic_acceleration = false;
    levenberg_marquardt(p, xn, o);
    EXPECT_NEAR(xn(0), newton, 1e-14) << "iteration " << k;
  }
  // Third order against second: after two steps from 1.5 Chebyshev is 6.6e-13 from √2, Newton
  // 2.1e-6.
  const Eigen::VectorXd two = Eigen::VectorXd::Constant(1, 1.5);
  Eigen::VectorXd a2 = two, n2 = two;
  o.max_iterations = 2;
  o.geodesic_acceleration = true;
  levenberg_marquardt(p, a2, o);
  o.geodesic_acceleration = false;
  levenberg_marquardt(p, n2, o);
  EXPECT_LT(std::abs(a2(0) - std::sqrt(2.0)), 1e-12);
  EXPECT_GT(std::abs(n2(0) - std::sqrt(2.0)), 1e-6);
}

// From x = 3 the accelerated step bends too much for its model: with λ = 0, 2|a|/|δ| = 4|δ|/r' =
// 4·(7/6)/6 = 0.78 > α = 0.75, so the trial is rejected and the first iterate is a damped one, not
// Chebyshev's (which the loop would take if it ignored the bound).
TEST(LevenbergMarquardt, TrialThatBendsTooMuchIsRejected) {
  const LeastSquaresProblem p = square_root_of_two();
  LevenbergMarquardtOptions o;
  o.initial_lambda = 0;
  const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(1, 3.0);
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  p.residuals(x0, r, &J);
  const LmTrial t = levenberg_marquardt_trial(p, x0, r, J, 0.0, o);
  ASSERT_TRUE(t.ok);
  EXPECT_NEAR(t.bend, 4.0 * (7.0 / 6.0) / 6.0, 1e-12);
  EXPECT_TRUE(t.bent);
  const double cheb = 3.0 - 7.0 / 6.0 - 2 * 49.0 / (2 * 216.0);
  Eigen::VectorXd x = x0;
  o.max_iterations = 1;
  levenberg_marquardt(p, x, o);
  EXPECT_GT(std::abs(x(0) - cheb), 1e-3) << x(0);
  EXPECT_LT(std::abs(x(0) - std::sqrt(2.0)), std::abs(3.0 - std::sqrt(2.0)));  // still a step towards √2
}

// r = (1, 1e-4 e^{-x}): Φ = 1 + 1e-8 e^{-2x} falls by a factor e^{-2} of its small part a step (the
// Gauss–Newton step is 1 in x) until it rounds to 1; over 10 iterations it falls by 1e-8 of Φ, below
// the stall test's 1e-6, so the loop stops Stalled (without the test it would stop at NoStep).
TEST(LevenbergMarquardt, StallsWhenPhiNoLongerFalls) {
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = Eigen::Vector2d(1.0, 1e-4 * std::exp(-x(0)));
    if (J) *J = Eigen::Vector2d(0.0, -1e-4 * std::exp(-x(0)));
  };
  LevenbergMarquardtOptions o;
  o.geodesic_acceleration = false;
  o.target = 0.5;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(1);
  const LsOutcome out = levenberg_marquardt(p, x, o);
  EXPECT_EQ(out.stop, LsStop::Stalled) << int(out.stop);
  EXPECT_GE(out.iterations, 10);
  EXPECT_GT(x(0), 5.0);
}

// The quadratic residuals as a problem, at x = (0.3, -1.1, 0.7): there the diagonal of JᵀJ is
// (9.25, 5.65, 50.36).
struct QuadraticAtX {
  LeastSquaresProblem p;
  Eigen::Vector3d x{0.3, -1.1, 0.7};
  Eigen::VectorXd r = quadratic_r(x);
  Eigen::MatrixXd J = quadratic_J(x);
  QuadraticAtX() {
    p.residuals = [](const Eigen::VectorXd& y, Eigen::VectorXd& ry, Eigen::MatrixXd* Jy) {
      ry = quadratic_r(y);
      if (Jy) *Jy = quadratic_J(y);
    };
  }
};

// The trial at λ = 0.3 against its closed form: δ = −(JᵀJ + λD)⁻¹Jᵀr, a = −(JᵀJ + λD)⁻¹Jᵀr_δδ
// and the bend 2‖a‖_D/‖δ‖_D, with D = diag JᵀJ (Marquardt's scaling) or max diag JᵀJ · Id
// (Levenberg's, o.marquardt_scaling = false). Returns δ.
Eigen::Vector3d expect_trial_closed_form(const LevenbergMarquardtOptions& o) {
  const QuadraticAtX q;
  const double lambda = 0.3;
  const LmTrial t = levenberg_marquardt_trial(q.p, q.x, q.r, q.J, lambda, o);
  EXPECT_TRUE(t.ok);
  const Eigen::Matrix3d A = q.J.transpose() * q.J;
  const Eigen::Vector3d D = o.marquardt_scaling ? Eigen::Vector3d(A.diagonal())
                                                : Eigen::Vector3d::Constant(A.diagonal().maxCoeff());
  Eigen::Matrix3d M = A;
  M.diagonal() += lambda * D;
  const Eigen::Vector3d d = -M.inverse() * (q.J.transpose() * q.r);
  const Eigen::Vector3d rdd(2 * d(0) * d(0) + 6 * d(0) * d(1), 2 * d(1) * d(1) - 4 * d(0) * d(2), 10 * d(2) * d(2));
  const Eigen::Vector3d a = -M.inverse() * (q.J.transpose() * rdd);
  EXPECT_LT((t.velocity - d).norm(), 1e-12 * d.norm());
  EXPECT_LT((t.acceleration - a).norm(), 1e-10 * a.norm());
  const double bend = 2 * std::sqrt(a.dot(D.asDiagonal() * a) / d.dot(D.asDiagonal() * d));
  EXPECT_NEAR(t.bend, bend, 1e-10 * bend);
  return d;
}

// The trial as the loop takes it (Marquardt's scaling, the default), and without acceleration.
TEST(LevenbergMarquardt, TrialIsTheDampedVelocityAndItsAcceleration) {
  expect_trial_closed_form(LevenbergMarquardtOptions{});
  const QuadraticAtX q;
  LevenbergMarquardtOptions o;
  o.geodesic_acceleration = false;
  const LmTrial plain = levenberg_marquardt_trial(q.p, q.x, q.r, q.J, 0.3, o);
  EXPECT_EQ(plain.acceleration.size(), 0);
  EXPECT_EQ(plain.bend, 0.0);
}

// Levenberg's scaling (marquardt_scaling = false): D = max diag JᵀJ · Id in the velocity, the
// acceleration and the bend; the diagonal of JᵀJ differs by 9× across the unknowns here, so the two
// velocities differ by far more than the tolerance.
TEST(LevenbergMarquardt, LevenbergScalingDampsEveryUnknownAlike) {
  LevenbergMarquardtOptions o;
  o.marquardt_scaling = false;
  const Eigen::Vector3d levenberg = expect_trial_closed_form(o);
  const Eigen::Vector3d marquardt = expect_trial_closed_form(LevenbergMarquardtOptions{});
  EXPECT_GT((marquardt - levenberg).norm(), 1e-3 * levenberg.norm());
}

// Rosenbrock's valley as least squares (the worked example of the header): both loops reach
// (1, 1); the accelerated one in fewer iterations.
TEST(LevenbergMarquardt, RosenbrockValley) {
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = Eigen::Vector2d(10 * (x(1) - x(0) * x(0)), 1 - x(0));
    if (J) {
      J->resize(2, 2);
      *J << -20 * x(0), 10, -1, 0;
    }
  };
  LevenbergMarquardtOptions o;
  o.target = 1e-10;
  int iterations[2] = {0, 0};
  for (int accel = 0; accel < 2; ++accel) {
    o.geodesic_acceleration = accel == 1;
    Eigen::VectorXd x = Eigen::Vector2d(-1.2, 1);
    const LsOutcome out = levenberg_marquardt(p, x, o);
    EXPECT_EQ(out.stop, LsStop::Reached) << "accelerated " << accel;
    EXPECT_LT((x - Eigen::Vector2d(1, 1)).norm(), 1e-9) << "accelerated " << accel;
    iterations[accel] = out.iterations;
  }
  EXPECT_LT(iterations[1], iterations[0]);
}

// The nearest point of the unit sphere to p: r(x) = x − p subject to |x|² = 1, answer p/|p|.
LeastSquaresProblem nearest_on_sphere(const Eigen::Vector3d& p) {
  LeastSquaresProblem q;
  q.residuals = [p](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = x - p;
    if (J) *J = Eigen::MatrixXd::Identity(3, 3);
  };
  q.constraint = [](const Eigen::VectorXd& x, Eigen::VectorXd* grad) {
    if (grad) *grad = 2 * x;
    return x.squaredNorm() - 1;
  };
  q.restore = [](Eigen::VectorXd& x) {
    const double s = x.norm();
    if (!(s > 0)) return false;
    x /= s;
    return true;
  };
  return q;
}

TEST(LevenbergMarquardt, ConstrainedStepIsTangentAndEndsAtTheNearestPoint) {
  const Eigen::Vector3d p(1.0, 2.0, -3.0);
  const LeastSquaresProblem q = nearest_on_sphere(p);
  // Off the constraint (|x|² = 1.69), with the quadratic residuals (so that the acceleration is not
  // rounding noise): the velocity meets the linearised constraint, ∇cᵀδ = −c, and the acceleration
  // is tangent to it, ∇cᵀa = 0.
  LeastSquaresProblem nq = q;
  nq.residuals = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = quadratic_r(x);
    if (J) *J = quadratic_J(x);
  };
  const Eigen::VectorXd x0 = Eigen::Vector3d(1.2, 0.5, 0.0);
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  nq.residuals(x0, r, &J);
  const LmTrial t = levenberg_marquardt_trial(nq, x0, r, J, 1e-3, LevenbergMarquardtOptions{});
  ASSERT_TRUE(t.ok);
  ASSERT_EQ(t.acceleration.size(), 3);
  ASSERT_GT(t.acceleration.norm(), 1e-3 * t.velocity.norm());
  EXPECT_NEAR((2 * x0).dot(t.velocity), -(x0.squaredNorm() - 1), 1e-14);
  EXPECT_NEAR((2 * x0).dot(t.acceleration), 0.0, 1e-13 * t.acceleration.norm());
  for (bool accel : {false, true}) {
    LevenbergMarquardtOptions o;
    o.geodesic_acceleration = accel;
    Eigen::VectorXd x = x0;
    const LsOutcome out = levenberg_marquardt(q, x, o);
    EXPECT_TRUE(out.stop == LsStop::Stalled || out.stop == LsStop::NoStep) << int(out.stop);
    EXPECT_LT((x - p.normalized()).norm(), 1e-7) << "accelerated " << accel;
    EXPECT_NEAR(x.norm(), 1.0, 1e-15);
  }
}

TEST(LevenbergMarquardt, UnmetConstraintAtTheStartLeavesTheStartAsGiven) {
  LeastSquaresProblem q = nearest_on_sphere(Eigen::Vector3d(1, 2, 3));
  q.restore = [](Eigen::VectorXd& x) {
    x.setConstant(7);  // a failed restoration may leave anything behind
    return false;
  };
  Eigen::VectorXd x = Eigen::Vector3d(0.5, 0.1, 0.2);
  const Eigen::VectorXd given = x;
  const LsOutcome out = levenberg_marquardt(q, x, LevenbergMarquardtOptions{});
  EXPECT_EQ(out.stop, LsStop::ConstraintUnmet);
  EXPECT_EQ(out.iterations, 0);
  EXPECT_EQ(x, given);
}

// The monitor sees the start and every accepted point with its Φ and can stop the loop
// (LsStop::Interrupted).
TEST(LevenbergMarquardt, MonitorSeesEveryAcceptedPointAndCanStop) {
  LeastSquaresProblem p = square_root_of_two();
  std::vector<double> seen;
  p.monitor = [&](const Eigen::VectorXd& x, int iterations, double phi) {
    EXPECT_EQ(iterations, static_cast<int>(seen.size()));
    EXPECT_NEAR(phi, std::pow(x(0) * x(0) - 2, 2), 1e-15);
    seen.push_back(x(0));
    return iterations < 2;
  };
  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 1.5);
  const LsOutcome out = levenberg_marquardt(p, x, LevenbergMarquardtOptions{});
  EXPECT_EQ(out.stop, LsStop::Interrupted);
  EXPECT_EQ(out.iterations, 2);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen.front(), 1.5);
  EXPECT_EQ(x(0), seen.back());
  // Stopped at the start: no step taken.
  p.monitor = [](const Eigen::VectorXd&, int, double) { return false; };
  x = Eigen::VectorXd::Constant(1, 1.5);
  EXPECT_EQ(levenberg_marquardt(p, x, LevenbergMarquardtOptions{}).iterations, 0);
  EXPECT_EQ(x(0), 1.5);
}

TEST(LevenbergMarquardt, BadInput) {
  const LeastSquaresProblem p = square_root_of_two();
  auto rejects = [&](LevenbergMarquardtOptions o, const std::string& name) {
    Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 1.5);
    try {
      levenberg_marquardt(p, x, o);
      ADD_FAILURE() << name << " accepted";
    } catch (const ParameterError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LevenbergMarquardtOptions o;
  o.target = -1;
  rejects(o, "target");
  o = {};
  o.target = nan;
  rejects(o, "target");
  o = {};
  o.max_iterations = -1;
  rejects(o, "max_iterations");
  o = {};
  o.initial_lambda = nan;
  rejects(o, "initial_lambda");
  o = {};
  o.geodesic_h = 0;
  rejects(o, "geodesic_h");
  o = {};
  o.geodesic_h = 1.5;
  rejects(o, "geodesic_h");
  o = {};
  o.geodesic_alpha = 0;
  rejects(o, "geodesic_alpha");

  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, nan);
  EXPECT_THROW(levenberg_marquardt(p, x, LevenbergMarquardtOptions{}), NonFiniteError);
  x = Eigen::Vector2d(1.5, 1.0);  // two unknowns for a one-column Jacobian
  EXPECT_THROW(levenberg_marquardt(p, x, LevenbergMarquardtOptions{}), SizeError);
  x.resize(0);  // no unknowns
  EXPECT_THROW(levenberg_marquardt(p, x, LevenbergMarquardtOptions{}), SizeError);
  // The trial checks its sizes and λ too.
  const Eigen::VectorXd x1 = Eigen::VectorXd::Constant(1, 1.5), r1 = Eigen::VectorXd::Constant(1, 0.25);
  EXPECT_THROW(levenberg_marquardt_trial(p, x1, r1, Eigen::MatrixXd::Ones(1, 2), 0.1, LevenbergMarquardtOptions{}),
               SizeError);
  EXPECT_THROW(levenberg_marquardt_trial(p, x1, Eigen::VectorXd::Ones(3), Eigen::MatrixXd::Ones(1, 1), 0.1,
                                         LevenbergMarquardtOptions{}),
               SizeError);
  EXPECT_THROW(levenberg_marquardt_trial(p, Eigen::VectorXd(), Eigen::VectorXd(), Eigen::MatrixXd(), 0.1,
                                         LevenbergMarquardtOptions{}),
               SizeError);
  EXPECT_THROW(levenberg_marquardt_trial(p, x1, r1, Eigen::MatrixXd::Constant(1, 1, 3.0), -1.0,
                                         LevenbergMarquardtOptions{}),
               ParameterError);
  // Missing callbacks, and a constraint gradient of the wrong size.
  x = x1;
  EXPECT_THROW(levenberg_marquardt(LeastSquaresProblem{}, x, LevenbergMarquardtOptions{}), ParameterError);
  LeastSquaresProblem c = nearest_on_sphere(Eigen::Vector3d(1, 2, 3));
  c.restore = nullptr;
  x = Eigen::Vector3d(1, 0, 0);
  EXPECT_THROW(levenberg_marquardt(c, x, LevenbergMarquardtOptions{}), ParameterError);
  c = nearest_on_sphere(Eigen::Vector3d(1, 2, 3));
  c.constraint = [](const Eigen::VectorXd& y, Eigen::VectorXd* grad) {
    if (grad) *grad = Eigen::VectorXd::Ones(5);
    return y.squaredNorm() - 1;
  };
  EXPECT_THROW(levenberg_marquardt(c, x, LevenbergMarquardtOptions{}), SizeError);
}

}  // namespace
}  // namespace bpde::optim
