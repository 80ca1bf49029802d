// Boundary curves (boundaries/boundary_curves.h): each form against a closed form, and the
// factories' typed errors.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "bezierpde/boundaries/boundary_curves.h"
#include "bezierpde/core/errors.h"

namespace {

using bpde::BoundaryCurve;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

TEST(BoundaryCurves, ArcCenterFormIsTheCircleByAngle) {
  // Default reference (1,0,0) with N = +z: c(t) = (cos a, sin a, 0) scaled and moved.
  const BoundaryCurve c = BoundaryCurve::arc(Vector3d(1, 2, 3), Vector3d(0, 0, 2), 0.5, 0.25, 2.0);
  for (double t : {0.0, 0.3, 0.7, 1.0}) {
    const double a = 0.25 + t * 1.75;
    EXPECT_LT((c.evaluate(t) - Vector3d(1 + 0.5 * std::cos(a), 2 + 0.5 * std::sin(a), 3)).norm(), 1e-15);
  }
  // N = +x: the default reference is (0,1,0), e2 = N x e1 = (0,0,1).
  const BoundaryCurve d = BoundaryCurve::arc(Vector3d::Zero(), Vector3d(1, 0, 0), 1, 0, kPi / 2);
  EXPECT_LT((d.evaluate(1) - Vector3d(0, 0, 1)).norm(), 1e-15);
  // A reference direction is projected onto the plane.
  const BoundaryCurve e = BoundaryCurve::arc(Vector3d::Zero(), Vector3d(0, 0, 1), 2, 0, kPi, Vector3d(0, 3, 5));
  EXPECT_LT((e.evaluate(0) - Vector3d(0, 2, 0)).norm(), 1e-15);
  EXPECT_LT((e.evaluate(0.5) - Vector3d(-2, 0, 0)).norm(), 1e-15);
}

TEST(BoundaryCurves, ArcThroughThreePointsIsTheCircleThroughThem) {
  // A tilted circle: points at angles 0.3, 1.0, 2.2 of the center form; the three-point form is
  // the same circle from angle 0.3 to 2.2, passing through the middle point.
  const Vector3d C(0.5, -1, 2), N = Vector3d(1, 2, 2).normalized();
  const BoundaryCurve full = BoundaryCurve::arc(C, N, 1.7, 0.0, 3.0);
  auto ang = [&](double a) { return full.evaluate(a / 3.0); };
  const BoundaryCurve c = BoundaryCurve::arc_through(ang(0.3), ang(1.0), ang(2.2));
  EXPECT_EQ(c.kind(), "arc");
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) EXPECT_LT((c.evaluate(t) - ang(0.3 + t * 1.9)).norm(), 1e-13) << t;
  // Its ends are the given points bit for bit (center + r e1 rounds them by ~1e-16, differently
  // with and without FMA contraction), so a corner shared with another edge is exact.
  EXPECT_EQ(c.start(), ang(0.3));
  EXPECT_EQ(c.end(), ang(2.2));
  // Through a point beyond a half turn: the arc goes the long way, via pm.
  const BoundaryCurve l = BoundaryCurve::arc_through(Vector3d(1, 0, 0), Vector3d(-1, 0, 0), Vector3d(0, -1, 0));
  EXPECT_LT((l.evaluate(1.0 / 3) - Vector3d(0, 1, 0)).norm(), 1e-15);  // angle π/2 of 3π/2
  EXPECT_LT((l.evaluate(1) - Vector3d(0, -1, 0)).norm(), 1e-15);
}

TEST(BoundaryCurves, HelixRisesByItsPitchPerTurn) {
  const BoundaryCurve h = BoundaryCurve::helix(Vector3d::Zero(), Vector3d(0, 0, 1), 2, 0, 4 * kPi, 3);
  EXPECT_LT((h.evaluate(0.125) - Vector3d(0, 2, 0.75)).norm(), 1e-14);  // a = π/2: a quarter turn, rise 3/4
  EXPECT_LT((h.evaluate(0.25) - Vector3d(-2, 0, 1.5)).norm(), 1e-14);
  EXPECT_LT((h.evaluate(1) - Vector3d(2, 0, 6)).norm(), 1e-14);
  // A tilted axis: the distance to the axis is the radius, the height is linear in the angle.
  const Vector3d c(1, 1, 0), N = Vector3d(1, -1, 1).normalized();
  const BoundaryCurve g = BoundaryCurve::helix(c, Vector3d(1, -1, 1), 0.5, 1.0, 3.0, -0.8);
  for (double t : {0.0, 0.4, 1.0}) {
    const Vector3d d = g.evaluate(t) - c;
    const double a = 1.0 + 2.0 * t;
    EXPECT_NEAR(d.dot(N), -0.8 * a / (2 * kPi), 1e-15);
    EXPECT_NEAR((d - d.dot(N) * N).norm(), 0.5, 1e-15);
  }
}

TEST(BoundaryCurves, BezierBSplineSegmentAndSamplesAgainstClosedForms) {
  Eigen::MatrixX3d P(3, 3);
  P << 0, 0, 0, 1, 2, 0, 2, 0, 1;
  const BoundaryCurve b = BoundaryCurve::bezier(P);
  // (1-t)² P0 + 2t(1-t) P1 + t² P2 at t = 1/4.
  EXPECT_LT((b.evaluate(0.25) - (0.5625 * P.row(0) + 0.375 * P.row(1) + 0.0625 * P.row(2)).transpose()).norm(), 1e-15);
  // A quadratic B-spline on [0,2] with one interior knot passes through the midpoint of its middle
  // leg at that knot (t = 1/2), and is clamped at the ends.
  Eigen::MatrixX3d Q(4, 3);
  Q << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1;
  const BoundaryCurve s = BoundaryCurve::bspline(2, {0, 0, 0, 1, 2, 2, 2}, Q);
  EXPECT_LT((s.evaluate(0.5) - 0.5 * (Q.row(1) + Q.row(2)).transpose()).norm(), 1e-15);
  EXPECT_LT((s.evaluate(0) - Q.row(0).transpose()).norm(), 1e-15);
  EXPECT_LT((s.evaluate(1) - Q.row(3).transpose()).norm(), 1e-15);
  const BoundaryCurve g = BoundaryCurve::segment(Vector3d(1, 0, 0), Vector3d(3, 2, 0));
  EXPECT_LT((g.evaluate(0.25) - Vector3d(1.5, 0.5, 0)).norm(), 1e-15);
  // Chord length: samples at x = 0, 1, 3 have parameters 0, 1/3, 1.
  Eigen::MatrixX3d S(3, 3);
  S << 0, 0, 0, 1, 0, 0, 3, 0, 0;
  const BoundaryCurve c = BoundaryCurve::samples(S);
  EXPECT_LT((c.evaluate(2.0 / 3) - Vector3d(2, 0, 0)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(c.as_samples()->params(1), 1.0 / 3);
  // Given parameters are mapped affinely onto [0,1].
  const BoundaryCurve d = BoundaryCurve::samples(S, {10, 15, 30});
  EXPECT_DOUBLE_EQ(d.as_samples()->params(1), 0.25);
}

// exact_tangent (used to decide which corners are smooth, fit_boundary.h): the direction of c'
// at each end, against finite differences of evaluate() (arc, helix, B-spline) and the first
// non-zero difference of a Bézier polygon; none for samples and functions.
TEST(BoundaryCurves, ExactTangentsAreTheDirectionsOfTheDerivative) {
  auto same_direction = [](const Vector3d& a, const Vector3d& b) {
    return a.normalized().cross(b.normalized()).norm() < 1e-6 && a.dot(b) > 0;
  };
  auto difference = [](const BoundaryCurve& c, bool at_end) {
    const double h = 1e-7;
    return at_end ? Vector3d((c.evaluate(1) - c.evaluate(1 - h)) / h) : Vector3d((c.evaluate(h) - c.evaluate(0)) / h);
  };
  Eigen::MatrixX3d Q(4, 3);
  Q << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1;
  const BoundaryCurve curves[] = {
      BoundaryCurve::arc(Vector3d(1, 2, 3), Vector3d(0, 1, 1), 1.5, 0.2, 2.4),
      BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, 3.0, 1.0),  // clockwise
      BoundaryCurve::helix(Vector3d::Zero(), Vector3d::UnitZ(), 2, 0.5, 4.0, 0.7),
      BoundaryCurve::bspline(2, {0, 0, 0, 1, 2, 2, 2}, Q),
      BoundaryCurve::bezier(Q),
  };
  for (const auto& c : curves)
    for (bool at_end : {false, true}) {
      ASSERT_TRUE(c.exact_tangent(at_end).has_value()) << c.kind();
      EXPECT_TRUE(same_direction(*c.exact_tangent(at_end), difference(c, at_end))) << c.kind() << " " << at_end;
    }
  // The arc's value is c' itself: r (a1 - a0) at unit speed in angle.
  EXPECT_NEAR(curves[0].exact_tangent(false)->norm(), 1.5 * 2.2, 1e-14);
  // A Bézier curve whose first legs vanish: the first non-zero difference (P_2 - P_0 here).
  Eigen::MatrixX3d D(4, 3);
  D << 0, 0, 0, 0, 0, 0, 1, 2, 0, 3, 3, 3;
  EXPECT_TRUE(same_direction(*BoundaryCurve::bezier(D).exact_tangent(false), Vector3d(1, 2, 0)));
  Eigen::MatrixX3d S(3, 3);
  S << 0, 0, 0, 1, 0, 0, 3, 0, 0;
  EXPECT_FALSE(BoundaryCurve::samples(S).exact_tangent(false).has_value());
  EXPECT_FALSE(BoundaryCurve::function([](double t) { return Vector3d(t, t * t, 0); }).exact_tangent(true));
}

TEST(BoundaryCurves, BadCurvesThrowTypedErrors) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(BoundaryCurve::bezier(Eigen::MatrixX3d::Zero(1, 3)), bpde::DegreeError);
  Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(3, 3);
  P(1, 1) = nan;
  EXPECT_THROW(BoundaryCurve::bezier(P), bpde::NonFiniteError);
  EXPECT_THROW(BoundaryCurve::bspline(2, {0, 0, 0, 1, 1, 1}, Eigen::MatrixX3d::Zero(4, 3)), bpde::SizeError);
  EXPECT_THROW(BoundaryCurve::arc(Vector3d::Zero(), Vector3d(0, 0, 1), 0.0, 0, 1), bpde::ParameterError);
  EXPECT_THROW(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::Zero(), 1.0, 0, 1), bpde::ParameterError);
  EXPECT_THROW(BoundaryCurve::arc(Vector3d::Zero(), Vector3d(0, 0, 1), 1.0, 1, 1), bpde::ParameterError);
  EXPECT_THROW(BoundaryCurve::arc(Vector3d::Zero(), Vector3d(0, 0, 1), 1.0, 0, 1, Vector3d(0, 0, 2)),
               bpde::ParameterError);
  EXPECT_THROW(BoundaryCurve::arc(Vector3d::Zero(), Vector3d(0, 0, 1), nan, 0, 1), bpde::NonFiniteError);
  EXPECT_THROW(BoundaryCurve::arc_through(Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2)),
               bpde::ParameterError);
  Eigen::MatrixX3d S = Eigen::MatrixX3d::Zero(3, 3);
  S(2, 0) = 1;
  EXPECT_THROW(BoundaryCurve::samples(S), bpde::ParameterError);  // points 0 and 1 coincide
  EXPECT_THROW(BoundaryCurve::samples(S, {0, 2, 1}), bpde::ParameterError);
  EXPECT_THROW(BoundaryCurve::samples(S, {0, 1}), bpde::SizeError);
  Eigen::MatrixX3d many = Eigen::MatrixX3d::Zero(BoundaryCurve::kMaxPoints + 1, 3);
  many.col(0).setLinSpaced(0, 1);
  EXPECT_THROW(BoundaryCurve::samples(many), bpde::SizeError);
  EXPECT_NO_THROW(BoundaryCurve::samples(many.topRows(BoundaryCurve::kMaxPoints)));
}

}  // namespace
