// triangular/triangular_net against exact polynomials and direct Bernstein sums.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/triangular/triangular_net.h"

using namespace bpde;

namespace {

// x = (a u + b v + c w)^n per coordinate: P_ijk = a^i b^j c^k exactly; derivatives exact.
struct LinearPower {
  int n;
  double a[3], b[3], c[3];
  TriangularNet net() const {
    TriangularNet N(n);
    for (int r = 0; r < N.size(); ++r) {
      const MultiIndex I = TriangularNet::multi_index(n, r);
      for (int k = 0; k < 3; ++k) N.points()(r, k) = std::pow(a[k], I[0]) * std::pow(b[k], I[1]) * std::pow(c[k], I[2]);
    }
    return N;
  }
  // d/du of (a u + b v + c (1-u-v))^n: coefficient (a - c), d/dv: (b - c)
  Eigen::Vector3d deriv(double u, double v, int du, int dv) const {
    Eigen::Vector3d out;
    const int d = du + dv;
    for (int k = 0; k < 3; ++k) {
      if (d > n) {
        out(k) = 0;
        continue;
      }
      const double L = a[k] * u + b[k] * v + c[k] * (1 - u - v);
      out(k) =
          factorial(n) / factorial(n - d) * std::pow(a[k] - c[k], du) * std::pow(b[k] - c[k], dv) * std::pow(L, n - d);
    }
    return out;
  }
};

LinearPower sample(int n) { return LinearPower{n, {1.1, 0.8, 0.9}, {0.7, 1.2, 1.0}, {0.9, 1.0, 1.15}}; }

}  // namespace

TEST(TriangularNet, IndexOrderFollowsFormats) {
  const int n = 3;
  EXPECT_EQ(TriangularNet::index(n, 3, 0), 0);  // P_{n00} first
  EXPECT_EQ(TriangularNet::index(n, 2, 1), 1);  // then i = n-1, j from n-i down
  EXPECT_EQ(TriangularNet::index(n, 2, 0), 2);
  EXPECT_EQ(TriangularNet::index(n, 0, 0), 9);  // P_{00n} last
  for (int r = 0; r < TriangularNet::count(n); ++r) {
    const MultiIndex I = TriangularNet::multi_index(n, r);
    EXPECT_EQ(I[0] + I[1] + I[2], n);
    EXPECT_EQ(TriangularNet::index(n, I[0], I[1]), r);
  }
}

TEST(TriangularNet, EvaluationMatchesDirectSumAndCorners) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  TriangularNet net(6);
  for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
  const Eigen::MatrixX2d uv = (Eigen::MatrixX2d(4, 2) << 0.2, 0.3, 0.0, 0.0, 1.0, 0.0, 0.1, 0.85).finished();
  const Eigen::MatrixX3d many = net.evaluate_many(uv);
  for (int s = 0; s < uv.rows(); ++s) {
    const double u = uv(s, 0), v = uv(s, 1), w = 1 - u - v;
    Eigen::Vector3d direct = Eigen::Vector3d::Zero();
    for (int r = 0; r < net.size(); ++r) {
      const MultiIndex I = TriangularNet::multi_index(6, r);
      direct += factorial(6) / (factorial(I[0]) * factorial(I[1]) * factorial(I[2])) * std::pow(u, I[0]) *
                std::pow(v, I[1]) * std::pow(w, I[2]) * net.points().row(r).transpose();
    }
    EXPECT_LT((net.evaluate(u, v) - direct).norm(), 1e-14);
    EXPECT_LT((many.row(s).transpose() - direct).norm(), 1e-14);
  }
  EXPECT_LT((net.evaluate(1, 0) - net.point(6, 0)).norm(), 1e-15);
  EXPECT_LT((net.evaluate(0, 1) - net.point(0, 6)).norm(), 1e-15);
  EXPECT_LT((net.evaluate(0, 0) - net.point(0, 0)).norm(), 1e-15);
}

TEST(TriangularNet, DerivativesOfExactPolynomialsUpToDegree25) {
  for (int n : {2, 5, 12, 25}) {
    const LinearPower p = sample(n);
    const TriangularNet net = p.net();
    for (auto [u, v] : {std::pair{0.2, 0.3}, std::pair{0.0, 0.0}, std::pair{0.6, 0.4}})
      for (int du = 0; du <= 3; ++du)
        for (int dv = 0; dv <= 3; ++dv) {
          const Eigen::Vector3d exact = p.deriv(u, v, du, dv);
          const double tol =
              1e-13 * exact.norm() + 1e-14 * std::pow(2.0 * n, du + dv) * net.points().cwiseAbs().maxCoeff();
          EXPECT_LT((net.derivative(u, v, du, dv) - exact).norm(), tol) << n << du << dv;
        }
    const Eigen::Vector2d d(0.6, -0.8);
    EXPECT_LT(
        (net.directional_derivative(0.3, 0.3, d) - (0.6 * p.deriv(0.3, 0.3, 1, 0) - 0.8 * p.deriv(0.3, 0.3, 0, 1)))
            .norm(),
        1e-12 * (1 + p.deriv(0.3, 0.3, 1, 0).norm()));
  }
}

TEST(TriangularNet, PartitionOfUnityAndElevation) {
  TriangularNet one(9);
  one.points().col(2).setOnes();
  EXPECT_NEAR(one.evaluate(0.3, 0.2).z(), 1.0, 1e-15);
  const TriangularNet net = sample(5).net();
  const TriangularNet e = net.elevated(3);
  EXPECT_EQ(e.n(), 8);
  for (auto [u, v] : {std::pair{0.1, 0.1}, std::pair{0.5, 0.5}, std::pair{0.0, 0.7}})
    EXPECT_LT((net.evaluate(u, v) - e.evaluate(u, v)).norm(), 1e-14);
}

TEST(TriangularNet, CurvatureOfParaboloid) {
  // (u, v, u^2 + v^2): P_ijk = (i/2, j/2, [i==2] + [j==2]) (blossoms); H = 2 at the origin (P_002).
  TriangularNet par(2);
  for (int r = 0; r < par.size(); ++r) {
    const MultiIndex I = TriangularNet::multi_index(2, r);
    par.points().row(r) << I[0] / 2.0, I[1] / 2.0, (I[0] == 2 ? 1.0 : 0.0) + (I[1] == 2 ? 1.0 : 0.0);
  }
  const auto g = par.geometry(0, 0);
  EXPECT_NEAR(g.H, 2.0, 1e-10);
  EXPECT_NEAR(g.K, 4.0, 1e-10);
  const double u = 0.2, v = 0.5, W2 = 1 + 4 * u * u + 4 * v * v;
  EXPECT_NEAR(par.geometry(u, v).K, 4 / (W2 * W2), 1e-10);
}

TEST(TriangularNet, Rings) {
  TriangularNet net(6);
  EXPECT_EQ(net.boundary_indices().size(), 18u);      // 3n
  EXPECT_EQ(net.adjacent_ring_indices().size(), 9u);  // 3(n-3)
  EXPECT_EQ(net.fixed_indices(FixedSet::BoundaryAdjacent).size(), 27u);
  EXPECT_EQ(net.free_indices(FixedSet::BoundaryAdjacent).size(), 1u);  // P_222
  EXPECT_THROW(net.fixed_indices(FixedSet::UBoundaries), UnsupportedProblem);
}

TEST(TriangularNet, SampleMesh) {
  TriangularNet flat(1);
  flat.set_point(1, 0, {1, 0, 0});  // P_100 = x(1,0)
  flat.set_point(0, 1, {0, 1, 0});  // P_010
  flat.set_point(0, 0, {0, 0, 0});  // P_001
  const TriangleMesh m = sample_mesh(flat, 5);
  ASSERT_EQ(m.V.rows(), 21);
  ASSERT_EQ(m.F.rows(), 25);
  EXPECT_NEAR(m.V(6, 0), 0.2, 1e-15);  // a = 1 starts at index N+1 = 6 with b = 0
  EXPECT_NEAR(m.V(6, 1), 0.0, 1e-15);
  double area = 0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double z = (b - a).cross(c - a).z();
    EXPECT_GT(z, 0);
    area += z / 2;
  }
  EXPECT_NEAR(area, 0.5, 1e-14);
}

TEST(TriangularNet, BadInputThrowsTypedErrors) {
  EXPECT_THROW(TriangularNet(0), DegreeError);
  EXPECT_THROW(TriangularNet(65), DegreeError);
  EXPECT_THROW(TriangularNet(3, Eigen::MatrixX3d::Zero(9, 3)), SizeError);
  Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(10, 3);
  P(2, 2) = -INFINITY;
  EXPECT_THROW(TriangularNet(3, P), NonFiniteError);
}
