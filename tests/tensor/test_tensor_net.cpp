// tensor/tensor_net and tensor/power_basis against exact polynomials.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/power_basis.h"
#include "bezierpde/tensor/tensor_net.h"

using namespace bpde;

namespace {

// f(u,v) = sum_t (a_t + b_t u)^n (c_t + d_t v)^m per coordinate: exact Bernstein coefficients
// a^(n-i) (a+b)^i c^(m-j) (c+d)^j and exact derivatives.
struct ProductPoly {
  int n, m;
  double a[3], b[3], c[3], d[3];
  TensorNet net() const {
    TensorNet N(n, m);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j)
        for (int k = 0; k < 3; ++k)
          N.points()(N.index(i, j), k) =
              std::pow(a[k], n - i) * std::pow(a[k] + b[k], i) * std::pow(c[k], m - j) * std::pow(c[k] + d[k], j);
    return N;
  }
  Eigen::Vector3d deriv(double u, double v, int du, int dv) const {
    Eigen::Vector3d out;
    for (int k = 0; k < 3; ++k) {
      const double fu =
          du > n ? 0 : factorial(n) / factorial(n - du) * std::pow(b[k], du) * std::pow(a[k] + b[k] * u, n - du);
      const double fv =
          dv > m ? 0 : factorial(m) / factorial(m - dv) * std::pow(d[k], dv) * std::pow(c[k] + d[k] * v, m - dv);
      out(k) = fu * fv;
    }
    return out;
  }
};

ProductPoly sample_poly(int n, int m) {
  return ProductPoly{n, m, {0.9, 1.0, 0.8}, {0.2, -0.3, 0.25}, {1.0, 0.7, 0.95}, {-0.1, 0.35, 0.15}};
}

}  // namespace

TEST(TensorNet, EvaluationMatchesDirectBernsteinSum) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(-1, 1);
  TensorNet net(5, 3);
  for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.61, 1.0}) {
      Eigen::Vector3d direct = Eigen::Vector3d::Zero();
      for (int i = 0; i <= 5; ++i)
        for (int j = 0; j <= 3; ++j)
          direct += binomial(5, i) * std::pow(u, i) * std::pow(1 - u, 5 - i) * binomial(3, j) * std::pow(v, j) *
                    std::pow(1 - v, 3 - j) * net.point(i, j);
      EXPECT_LT((net.evaluate(u, v) - direct).norm(), 1e-14);
    }
}

TEST(TensorNet, DerivativesOfExactPolynomialsUpToDegree25) {
  for (auto [n, m] : {std::pair{3, 2}, std::pair{10, 7}, std::pair{25, 25}, std::pair{25, 4}}) {
    const ProductPoly p = sample_poly(n, m);
    const TensorNet net = p.net();
    Eigen::VectorXd us(3), vs(2);
    us << 0.0, 0.37, 1.0;
    vs << 0.22, 0.9;
    for (int du = 0; du <= 3; ++du)
      for (int dv = 0; dv <= 3; ++dv) {
        const Eigen::MatrixX3d grid = net.evaluate_grid(us, vs, du, dv);
        for (int a = 0; a < us.size(); ++a)
          for (int b = 0; b < vs.size(); ++b) {
            const Eigen::Vector3d exact = p.deriv(us(a), vs(b), du, dv);
            // rounding model of forward differences: eps * n^du m^dv 2^(du+dv) * max|P|
            const double tol = 1e-13 * exact.norm() + 1e-14 * std::pow(2.0 * n, du) * std::pow(2.0 * m, dv) *
                                                          net.points().cwiseAbs().maxCoeff();
            EXPECT_LT((net.derivative(us(a), vs(b), du, dv) - exact).norm(), tol) << n << " " << du << dv;
            EXPECT_LT((grid.row(a * vs.size() + b).transpose() - exact).norm(), tol) << n << " " << du << dv;
          }
      }
  }
}

TEST(TensorNet, PartitionOfUnity) {
  TensorNet net(7, 4);
  net.points().col(0).setOnes();  // x == 1 everywhere
  for (double u : {0.0, 0.2, 0.77})
    for (double v : {0.1, 1.0}) EXPECT_NEAR(net.evaluate(u, v).x(), 1.0, 1e-15);
}

TEST(TensorNet, ElevationKeepsTheSurface) {
  const TensorNet net = sample_poly(6, 3).net();
  const TensorNet e = net.elevated(4, 2);
  EXPECT_EQ(e.n(), 10);
  EXPECT_EQ(e.m(), 5);
  for (double u : {0.0, 0.45, 1.0})
    for (double v : {0.3, 0.8}) EXPECT_LT((net.evaluate(u, v) - e.evaluate(u, v)).norm(), 1e-14);
}

TEST(TensorNet, PowerBasisRoundTrip) {
  // x = (u, v, 1 + 2u - 3uv + u^2 v^3) has known monomial coefficients.
  Eigen::MatrixX3d c = Eigen::MatrixX3d::Zero(5 * 5, 3);
  auto at = [](int k, int l) { return k * 5 + l; };
  c(at(1, 0), 0) = 1;
  c(at(0, 1), 1) = 1;
  c(at(0, 0), 2) = 1;
  c(at(1, 0), 2) = 2;
  c(at(1, 1), 2) = -3;
  c(at(2, 3), 2) = 1;
  const TensorNet net = from_power(4, 4, c);
  EXPECT_NEAR(net.evaluate(0.5, 0.5).z(), 1 + 1 - 0.75 + 0.25 * 0.125, 1e-14);
  EXPECT_LT((to_power(net) - c).cwiseAbs().maxCoeff(), 1e-13);
  const Eigen::MatrixX3d a = to_factorial_power(net);
  EXPECT_NEAR(a(at(2, 3), 2), 2.0 * 6.0, 1e-12);  // a_kl = k! l! c_kl
  EXPECT_LT((from_factorial_power(4, 4, a).points() - net.points()).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(TensorNet, PowerBasisRoundTripErrorGrowsWithDegree) {
  // The measured growth is documented in docs/accuracy.md; here we only pin that it stays small
  // at moderate degree and that it really is a loss (not exact) at high degree.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  auto roundtrip = [&](int n) {
    TensorNet net(n, n);
    for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
    return (from_power(n, n, to_power(net)).points() - net.points()).cwiseAbs().maxCoeff();
  };
  EXPECT_LT(roundtrip(5), 1e-12);
  EXPECT_LT(roundtrip(10), 1e-6);
  EXPECT_GT(roundtrip(30), 1e-6);
}

TEST(TensorNet, CurvatureOfParaboloidAndSaddle) {
  // z = u^2 + v^2 on [0,1]^2: H = +2, K = 4 at the origin (FORMATS.md sign convention).
  TensorNet par(2, 2);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) par.set_point(i, j, {i / 2.0, j / 2.0, (i == 2 ? 1.0 : 0.0) + (j == 2 ? 1.0 : 0.0)});
  auto g = par.geometry(0, 0);
  ASSERT_TRUE(g.regular);
  EXPECT_NEAR(g.H, 2.0, 1e-10);
  EXPECT_NEAR(g.K, 4.0, 1e-10);
  // H of a graph z = f at a general point: ((1+fv^2) fuu - 2 fu fv fuv + (1+fu^2) fvv) / (2 W^3)
  const double u = 0.3, v = 0.6, fu = 2 * u, fv = 2 * v, W = std::sqrt(1 + fu * fu + fv * fv);
  g = par.geometry(u, v);
  EXPECT_NEAR(g.H, ((1 + fv * fv) * 2 + (1 + fu * fu) * 2) / (2 * W * W * W), 1e-10);
  EXPECT_NEAR(g.K, 4 / (W * W * W * W), 1e-10);
  // bilinear saddle z = uv: K = -1/(1+u^2+v^2)^2, H = -uv/(1+u^2+v^2)^(3/2)
  TensorNet saddle(1, 1);
  saddle.set_point(0, 0, {0, 0, 0});
  saddle.set_point(1, 0, {1, 0, 0});
  saddle.set_point(0, 1, {0, 1, 0});
  saddle.set_point(1, 1, {1, 1, 1});
  g = saddle.geometry(u, v);
  const double q = 1 + u * u + v * v;
  EXPECT_NEAR(g.K, -1 / (q * q), 1e-10);
  EXPECT_NEAR(g.H, -u * v / std::pow(q, 1.5), 1e-10);
  EXPECT_NEAR(saddle.geometry(0, 0).H, 0.0, 1e-12);
}

TEST(TensorNet, RingsAndFixedSets) {
  TensorNet net(4, 5);
  EXPECT_EQ(net.boundary_indices().size(), 2u * 5 + 2u * 4);  // 2(n+m)
  EXPECT_EQ(net.adjacent_ring_indices().size(), 2u * 3 + 2u * 2);
  EXPECT_EQ(net.fixed_indices(FixedSet::BoundaryAdjacent).size(), 30u - 1u * 2);
  EXPECT_EQ(net.fixed_indices(FixedSet::UBoundaries).size(), 12u);
  EXPECT_EQ(net.free_indices(FixedSet::Boundary).size(), 3u * 4u);
}

TEST(TensorNet, SampleMeshOrderAndOrientation) {
  TensorNet flat(1, 1);
  flat.set_point(0, 0, {0, 0, 0});
  flat.set_point(1, 0, {1, 0, 0});
  flat.set_point(0, 1, {0, 1, 0});
  flat.set_point(1, 1, {1, 1, 0});
  const TriangleMesh m = sample_mesh(flat, 4);
  ASSERT_EQ(m.V.rows(), 25);
  ASSERT_EQ(m.F.rows(), 32);
  EXPECT_NEAR(m.V(1 * 5 + 3, 0), 0.25, 1e-15);  // index a(N+1)+b is (u,v) = (a/N, b/N)
  EXPECT_NEAR(m.V(1 * 5 + 3, 1), 0.75, 1e-15);
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    EXPECT_GT((b - a).cross(c - a).z(), 0);  // agrees with x_u ^ x_v = +z
  }
}

TEST(TensorNet, BadInputThrowsTypedErrors) {
  EXPECT_THROW(TensorNet(0, 3), DegreeError);
  EXPECT_THROW(TensorNet(-1, 3), DegreeError);
  EXPECT_THROW(TensorNet(65, 3), DegreeError);
  EXPECT_THROW(TensorNet(2, 2, Eigen::MatrixX3d::Zero(8, 3)), SizeError);
  Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(9, 3);
  P(4, 1) = std::nan("");
  EXPECT_THROW(TensorNet(2, 2, P), NonFiniteError);
  P(4, 1) = INFINITY;
  EXPECT_THROW(TensorNet(2, 2, P), NonFiniteError);
  EXPECT_THROW(from_power(2, 2, Eigen::MatrixX3d::Zero(5, 3)), SizeError);
  EXPECT_THROW(TensorNet(2, 2).derivative_points(3, 0), DegreeError);
}
