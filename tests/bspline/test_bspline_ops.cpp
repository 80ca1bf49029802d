// tensor/bspline_ops: knot insertion, Bézier extraction and blossoming leave the surface unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "bezierpde/core/errors.h"
#include "tests/bspline/helpers.h"

using namespace bpde;
using namespace bpde::testing;

namespace {

double max_eval_diff(const BSplineNet& a, const BSplineNet& b, int du = 0, int dv = 0) {
  double d = 0;
  for (int s = 0; s <= 13; ++s)
    for (int t = 0; t <= 11; ++t) {
      const double u = a.u_min() + (a.u_max() - a.u_min()) * s / 13.0;
      const double v = a.v_min() + (a.v_max() - a.v_min()) * t / 11.0;
      const Eigen::Vector3d e = a.derivative(u, v, du, dv);
      d = std::max(d, (e - b.derivative(u, v, du, dv)).norm() / (1 + e.norm()));  // relative
    }
  return d;
}

}  // namespace

TEST(BSplineOps, CurveKnotInsertionMatchesHandComputedBoehmStep) {
  // Quadratic, knots 0 0 0 1 2 2 2, points 0, 1, 3, 4 (1-D). Insert t = 0.5 (span [0,1]):
  // a_1 = (0.5-0)/(1-0) = 0.5, a_2 = (0.5-0)/(2-0) = 0.25:
  // Q = 0, 0.5*1 + 0.5*0, 0.25*3 + 0.75*1, 3, 4 = 0, 0.5, 1.5, 3, 4.
  Eigen::MatrixXd P(4, 1);
  P << 0, 1, 3, 4;
  const KnotRefinement r = insert_knot(2, {0, 0, 0, 1, 2, 2, 2}, P, 0.5);
  ASSERT_EQ(r.points.rows(), 5);
  const std::vector<double> expect_knots{0, 0, 0, 0.5, 1, 2, 2, 2};
  EXPECT_EQ(r.knots, expect_knots);
  Eigen::VectorXd expect(5);
  expect << 0, 0.5, 1.5, 3, 4;
  EXPECT_LT((r.points.col(0) - expect).norm(), 1e-15);
}

TEST(BSplineOps, KnotInsertionLeavesSurfaceUnchanged) {
  const std::vector<double> U = clamped(4, {0.2, 0.5, 0.5}, 0, 1), V = uniform(11);  // cubic unclamped in v
  const BSplineNet net = random_net(4, 3, U, V, 7);
  // New knots: new ones, existing ones (raising multiplicity), the ends of the unclamped v domain.
  const BSplineNet ref = insert_knots(net, {0.35, 0.5, 0.2, 0.35, 0.9}, {4.5, 5, 5, 3, 7, 6.25});
  EXPECT_EQ(ref.nu(), net.nu() + 5);
  EXPECT_EQ(ref.nv(), net.nv() + 6);
  EXPECT_DOUBLE_EQ(ref.u_min(), net.u_min());
  EXPECT_DOUBLE_EQ(ref.v_max(), net.v_max());
  for (int du = 0; du <= 2; ++du)
    for (int dv = 0; dv <= 2; ++dv) EXPECT_LT(max_eval_diff(net, ref, du, dv), 1e-12) << du << " " << dv;
}

TEST(BSplineOps, BezierPatchesReproduceEverySpanAndItsDerivatives) {
  // u: cubic, knots -1^4 .25 .6 .6 2^4 -> spans [-1,.25], [.25,.6], [.6,2];
  // v: quartic on uniform knots 0..9 (unclamped) -> 5 points, one span [4,5].
  const std::vector<double> U = clamped(3, {0.25, 0.6, 0.6}, -1, 2), V = uniform(10);
  const BSplineNet net = random_net(3, 4, U, V, 11);
  const std::vector<BezierPatch> patches = bezier_patches(net);
  ASSERT_EQ(patches.size(), 3u);
  for (const BezierPatch& b : patches) {
    const double hu = b.u1 - b.u0, hv = b.v1 - b.v0;
    for (double s : {0.1, 0.5, 0.93})
      for (double t : {0.05, 0.7})
        for (int du = 0; du <= 3; ++du)
          for (int dv = 0; dv <= 2; ++dv) {
            const Eigen::Vector3d a = b.net.derivative(s, t, du, dv) / (std::pow(hu, du) * std::pow(hv, dv));
            const Eigen::Vector3d e = net.derivative(b.u0 + hu * s, b.v0 + hv * t, du, dv);
            EXPECT_LT((a - e).norm(), 1e-11 * (1 + e.norm())) << b.su << " " << du << " " << dv;
          }
  }
}

TEST(BSplineOps, ContinuityAcrossKnotsIsDegreeMinusMultiplicity) {
  // Cubic in u: the simple knot .25 gives C^2 (the 3rd derivative jumps), the double knot .6 C^1.
  const std::vector<double> U = clamped(3, {0.25, 0.6, 0.6}, -1, 2), V = uniform(10);
  const BSplineNet net = random_net(3, 4, U, V, 12);
  const std::vector<BezierPatch> P = bezier_patches(net);
  auto jump = [&](int left, int du, double t) {
    const BezierPatch &a = P[static_cast<size_t>(left)], &b = P[static_cast<size_t>(left) + 1];
    const Eigen::Vector3d da = a.net.derivative(1.0, t, du, 0) / std::pow(a.u1 - a.u0, du);
    const Eigen::Vector3d db = b.net.derivative(0.0, t, du, 0) / std::pow(b.u1 - b.u0, du);
    return (da - db).norm() / (1 + da.norm());
  };
  for (double t : {0.0, 0.3, 1.0}) {
    for (int du = 0; du <= 2; ++du) EXPECT_LT(jump(0, du, t), 1e-12) << "knot .25, order " << du;
    EXPECT_GT(jump(0, 3, t), 1e-3);
    for (int du = 0; du <= 1; ++du) EXPECT_LT(jump(1, du, t), 1e-12) << "knot .6, order " << du;
    EXPECT_GT(jump(1, 2, t), 1e-3);
  }
}

TEST(BSplineOps, ExtractionHandlesAnInteriorKnotOfFullMultiplicity) {
  // Cubic with the knot 0.5 of multiplicity 4 (a C^-1 join): the two Bézier pieces are exactly
  // the two halves of the control polygon.
  const std::vector<double> U = clamped(3, {0.5, 0.5, 0.5, 0.5});
  const BezierExtraction ex = bezier_extraction(3, U);
  ASSERT_EQ(ex.spans(), 2);
  EXPECT_EQ(ex.first[0], 0);
  EXPECT_EQ(ex.first[1], 4);
  Eigen::MatrixXd left = Eigen::MatrixXd::Zero(4, 8), right = Eigen::MatrixXd::Zero(4, 8);
  left.leftCols(4).setIdentity();
  right.rightCols(4).setIdentity();
  EXPECT_LT((ex.C[0] - left).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((ex.C[1] - right).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(BSplineOps, SingleSpanClampedExtractionIsTheIdentity) {
  const BSplineNet net = random_net(4, 2, clamped(4, {}, 0, 1), clamped(2, {}, 0, 1), 3);
  const std::vector<BezierPatch> P = bezier_patches(net);
  ASSERT_EQ(P.size(), 1u);
  EXPECT_LT((P[0].net.points() - net.points()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(BSplineOps, BlossomingRepresentsPolynomialsExactlyOnAnyKnots) {
  // A bidegree-(3,2) polynomial patch on [0.5, 2] x [-1, 1], represented at degree (5, 4) on
  // unclamped, non-uniform knots whose domain is a sub-rectangle (degree elevation + blossoms).
  TensorNet bez(3, 2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> R(-1, 1);
  for (int r = 0; r < bez.size(); ++r) bez.points().row(r) << R(rng), R(rng), R(rng);
  const std::vector<double> U{0, 0.1, 0.3, 0.6, 0.7, 0.8, 1.1, 1.2, 1.5, 1.7, 1.9, 2.4, 2.5, 3.0};
  const std::vector<double> V{-2, -1.5, -1.0, -0.9, -0.2, 0.0, 0.3, 0.8, 1.2, 1.3, 1.6, 2};
  const BSplineNet net = bspline_from_bezier(bez, 0.5, 2, -1, 1, 5, 4, U, V);
  for (int s = 0; s <= 10; ++s)
    for (int t = 0; t <= 10; ++t) {
      const double u = net.u_min() + (net.u_max() - net.u_min()) * s / 10,
                   v = net.v_min() + (net.v_max() - net.v_min()) * t / 10;
      const Eigen::Vector3d e = bez.evaluate((u - 0.5) / 1.5, (v + 1) / 2);
      EXPECT_LT((net.evaluate(u, v) - e).norm(), 1e-13);
    }
}

TEST(BSplineOps, BadInputThrowsTypedErrors) {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(4, 3);
  const std::vector<double> K{0, 0, 0, 1, 2, 2, 2};
  EXPECT_THROW(insert_knot(2, K, P, 2.5), ParameterError);     // outside the domain
  EXPECT_THROW(insert_knot(2, K, P, 1.0, 3), ParameterError);  // multiplicity 4 > 3
  EXPECT_THROW(insert_knot(2, K, P, std::nan(""), 1), NonFiniteError);
  EXPECT_THROW(insert_knot(2, K, Eigen::MatrixXd::Zero(5, 3), 1.0), SizeError);
  EXPECT_THROW(insert_knot(2, {0, 0, 0, 2, 1, 2, 2}, P, 1.0), ParameterError);  // decreasing knots
  EXPECT_THROW(bezier_extraction(3, {0, 0, 0, 0, 1, 1, 1}), SizeError);         // too few knots
  EXPECT_THROW(bezier_extraction(0, {0, 1}), DegreeError);
  EXPECT_THROW(polynomial_to_bspline_matrix(4, 0, 1, 3, {0, 0, 0, 0, 1, 1, 1, 1}), DegreeError);
  EXPECT_THROW(polynomial_to_bspline_matrix(2, 1, 1, 3, {0, 0, 0, 0, 1, 1, 1, 1}), ParameterError);
  // The net constructor: wrong knot count for the points, non-monotone knots, degree mismatch.
  EXPECT_THROW(BSplineNet(3, 3, clamped(3, {}), clamped(3, {0.5}), Eigen::MatrixX3d::Zero(16, 3)), SizeError);
  EXPECT_THROW(BSplineNet(3, 3, {0, 0, 0, 0, 0.6, 0.4, 1, 1, 1, 1}, clamped(3, {}), Eigen::MatrixX3d::Zero(24, 3)),
               ParameterError);
  EXPECT_THROW(BSplineNet(3, 3, clamped(2, {}), clamped(3, {}), Eigen::MatrixX3d::Zero(12, 3)), SizeError);
}

TEST(BSplineNetDeBoor, AgreesWithBasisEvaluationOnGeneralKnots) {
  // non-uniform, repeated interior knot, unclamped ends
  const std::vector<double> U = {-0.5, 0.0, 0.1, 0.4, 0.4, 0.7, 1.3, 1.5, 2.0};  // p = 3: 5 points
  const std::vector<double> V = {0.0, 0.0, 0.0, 0.3, 0.8, 1.0, 1.0, 1.0};        // q = 2: 5 points
  Eigen::MatrixX3d P(25, 3);
  for (int r = 0; r < 25; ++r) P.row(r) << std::sin(1.0 + r), std::cos(0.3 * r), 0.1 * r * r;
  const bpde::BSplineNet net(3, 2, U, V, P);
  for (double u : {0.4, 0.55, 0.4000001, 1.3})
    for (double v : {0.0, 0.25, 0.3, 0.99, 1.0})
      EXPECT_LT((net.evaluate_de_boor(u, v) - net.evaluate(u, v)).norm(), 1e-13) << u << " " << v;
}
