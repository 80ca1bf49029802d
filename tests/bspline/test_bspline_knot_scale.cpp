// Knot vectors whose arithmetic overflows or loses the domain: rejected when the net is
// built, and basis_table never indexes from a non-finite parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/bspline_net.h"

using namespace bpde;

namespace {

Eigen::MatrixX3d grid_points(int nu, int nv) {
  Eigen::MatrixX3d P(nu * nv, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) P.row(i * nv + j) << i, j, (i * j) % 3;
  return P;
}

BSplineNet net_with_u(const std::vector<double>& U) {
  const std::vector<double> V = {0, 0, 1, 1};
  return BSplineNet(1, 1, U, V, grid_points(static_cast<int>(U.size()) - 2, 2));
}

}  // namespace

TEST(BSplineKnotScale, OverflowingWidthsAreRejectedWithTheKnotNamed) {
  for (const std::vector<double>& U :
       {std::vector<double>{-1e308, -1e308, 1e308, 1e308}, std::vector<double>{0, 0, 1e308, 1e308},
        std::vector<double>{0, 0, 1.7e308, 1.7e308}, std::vector<double>{0, 0, 1e51, 1e51}}) {
    try {
      net_with_u(U);
      ADD_FAILURE() << "accepted knots up to " << U.back();
    } catch (const ParameterError& e) {
      EXPECT_NE(std::string(e.what()).find("knot u["), std::string::npos) << e.what();
    }
  }
}

TEST(BSplineKnotScale, BadlyScaledDomainsAndSpansAreRejected) {
  // The domain holds too few doubles (width 1e-6 at 1e6), or is below 1e-50.
  EXPECT_THROW(net_with_u({1e6, 1e6, 1e6 + 1e-6, 1e6 + 1e-6}), ParameterError);
  EXPECT_THROW(net_with_u({0, 0, 1e-60, 1e-60}), ParameterError);
  // A non-zero span of 1e-15 of the knot vector's width.
  EXPECT_THROW(net_with_u({0, 0, 1e-15, 1, 1}), ParameterError);
  // Non-finite knots stay NonFiniteError.
  EXPECT_THROW(net_with_u({0, 0, std::numeric_limits<double>::infinity(), 1}), NonFiniteError);
}

TEST(BSplineKnotScale, KnotsJustInsideTheLimitsWorkEndToEnd) {
  for (const std::vector<double>& U :
       {std::vector<double>{-1e50, -1e50, 1e50, 1e50}, std::vector<double>{0, 0, 1e-50, 1e-50},
        std::vector<double>{0, 0, 1e-11, 1, 1}, std::vector<double>{1e6, 1e6, 1e6 + 0.1, 1e6 + 0.1}}) {
    const BSplineNet net = net_with_u(U);
    const TriangleMesh mesh = sample_mesh(net, 4);
    EXPECT_TRUE(mesh.V.allFinite()) << U.back();
    EXPECT_TRUE(net.evaluate(0.5 * (net.u_min() + net.u_max()), 0.5).allFinite());
  }
}

TEST(BSplineKnotScale, NonFiniteParametersThrowInsteadOfIndexingPastTheTable) {
  const std::vector<double> K = {0, 0, 0, 0.5, 1, 1, 1};
  Eigen::VectorXd t(3);
  t << 0.25, std::numeric_limits<double>::quiet_NaN(), 0.75;
  EXPECT_THROW(BSplineNet::basis_table(2, K, t), NonFiniteError);
  t(1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(BSplineNet::basis_table(2, K, t, 1), NonFiniteError);
  const BSplineNet net = net_with_u({0, 0, 0.5, 1, 1});
  EXPECT_THROW(net.evaluate(std::nan(""), 0.5), NonFiniteError);
  EXPECT_THROW(net.evaluate_de_boor(0.5, std::nan("")), NonFiniteError);
  // Finite parameters outside the domain are still clamped (unchanged behaviour).
  EXPECT_TRUE(net.evaluate(-5, 7).isApprox(net.evaluate(0, 1)));
}
