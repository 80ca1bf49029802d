// Tests of the BFS C¹ bicubic element (solvers/blend/bfs_element.h).
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <random>

#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/blend/bfs_element.h"

namespace bpde {
namespace {

/// A bicubic polynomial u = Σ c(i,j) x^i y^j (i, j <= 3), with exact derivatives and exact
/// integrals of products of derivatives.
struct Bicubic {
  Eigen::Matrix4d c;
  static double dpow(int i, int r, double x) {  // d^r/dx^r x^i
    if (r > i) return 0;
    double f = 1;
    for (int s = 0; s < r; ++s) f *= i - s;
    return f * std::pow(x, i - r);
  }
  double d(double x, double y, int rx, int ry) const {
    double s = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) s += c(i, j) * dpow(i, rx, x) * dpow(j, ry, y);
    return s;
  }
  /// Coefficients of the derivative as a polynomial (same 4x4 layout).
  Eigen::Matrix4d deriv(int rx, int ry) const {
    Eigen::Matrix4d out = Eigen::Matrix4d::Zero();
    for (int i = rx; i < 4; ++i)
      for (int j = ry; j < 4; ++j) {
        double f = 1;
        for (int s = 0; s < rx; ++s) f *= i - s;
        for (int s = 0; s < ry; ++s) f *= j - s;
        out(i - rx, j - ry) = f * c(i, j);
      }
    return out;
  }
};

/// ∫_[0,1]² p q for polynomials given by 4x4 coefficient arrays.
double integral_product(const Eigen::Matrix4d& p, const Eigen::Matrix4d& q) {
  double s = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) s += p(i, j) * q(a, b) / ((i + a + 1.0) * (j + b + 1.0));
  return s;
}

Eigen::MatrixX3d interpolate_bicubics(const BfsSpace& V, const Bicubic (&u)[3]) {
  return V.interpolate([&](double x, double y) {
    Eigen::Matrix<double, 4, 3> J;
    for (int c = 0; c < 3; ++c) {
      J(0, c) = u[c].d(x, y, 0, 0);
      J(1, c) = u[c].d(x, y, 1, 0);
      J(2, c) = u[c].d(x, y, 0, 1);
      J(3, c) = u[c].d(x, y, 1, 1);
    }
    return J;
  });
}

Bicubic random_bicubic(std::mt19937& rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  Bicubic b;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) b.c(i, j) = U(rng);
  return b;
}

TEST(HermiteCubic, KroneckerPropertiesAtTheEnds) {
  const auto v0 = hermite_cubic(0, 0), v1 = hermite_cubic(1, 0);
  const auto d0 = hermite_cubic(0, 1), d1 = hermite_cubic(1, 1);
  const double ev0[4] = {1, 0, 0, 0}, ev1[4] = {0, 0, 1, 0}, ed0[4] = {0, 1, 0, 0}, ed1[4] = {0, 0, 0, 1};
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(v0[i], ev0[i]);
    EXPECT_DOUBLE_EQ(v1[i], ev1[i]);
    EXPECT_DOUBLE_EQ(d0[i], ed0[i]);
    EXPECT_DOUBLE_EQ(d1[i], ed1[i]);
  }
  // derivatives against central differences
  for (double t : {0.1, 0.37, 0.8})
    for (int r = 0; r < 3; ++r) {
      const auto p = hermite_cubic(t + 1e-6, r), m = hermite_cubic(t - 1e-6, r), d = hermite_cubic(t, r + 1);
      for (int i = 0; i < 4; ++i) EXPECT_NEAR((p[i] - m[i]) / 2e-6, d[i], 1e-7);
    }
  EXPECT_EQ(hermite_cubic(0.3, 4)[0], 0.0);
  EXPECT_THROW(hermite_cubic(0.3, -1), ParameterError);
}

TEST(BfsSpace, ReproducesBicubicPolynomialsAndTheirDerivatives) {
  std::mt19937 rng(7);
  const Bicubic u[3] = {random_bicubic(rng), random_bicubic(rng), random_bicubic(rng)};
  const BfsSpace V(5, 3);
  const Eigen::MatrixX3d C = interpolate_bicubics(V, u);
  std::uniform_real_distribution<double> U(0, 1);
  for (int s = 0; s < 50; ++s) {
    const double x = U(rng), y = U(rng);
    for (int rx = 0; rx <= 3; ++rx)
      for (int ry = 0; ry <= 3; ++ry) {
        const Eigen::Vector3d v = V.evaluate(C, x, y, rx, ry);
        // rounding grows like h^-(rx+ry) for the higher derivatives
        for (int c = 0; c < 3; ++c) {
          const double e = u[c].d(x, y, rx, ry);
          EXPECT_NEAR(v(c), e, 1e-13 * std::pow(10.0, rx + ry) * (1 + std::abs(e))) << rx << ry;
        }
      }
  }
  // node and element-side points, corners
  for (double x : {0.0, 0.2, 0.6, 1.0})
    for (double y : {0.0, 1.0 / 3, 1.0}) {
      const Eigen::Vector3d v = V.evaluate(C, x, y, 1, 1);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(v(c), u[c].d(x, y, 1, 1), 1e-11);
    }
}

TEST(BfsSpace, FormMatrixGivesTheExactEnergyOfBicubics) {
  std::mt19937 rng(11);
  for (double a : {1.0, 10.0, 0.3}) {
    const Bicubic u[3] = {random_bicubic(rng), random_bicubic(rng), random_bicubic(rng)};
    const BfsSpace V(4, 3);
    const Eigen::MatrixX3d C = interpolate_bicubics(V, u);
    const Eigen::SparseMatrix<double> R = V.assemble_form(SecondOrderForm::from_a(a));
    double exact = 0;
    for (int c = 0; c < 3; ++c) {
      const auto uxx = u[c].deriv(2, 0), uxy = u[c].deriv(1, 1), uyy = u[c].deriv(0, 2);
      exact += integral_product(uxx, uxx) + 2 * a * integral_product(uxy, uxy) + a * a * integral_product(uyy, uyy);
    }
    const double got = (C.transpose() * (R * C)).trace();
    EXPECT_NEAR(got, exact, 1e-11 * exact) << a;
    // symmetric, and the affine functions are in its kernel
    EXPECT_NEAR((Eigen::MatrixXd(R) - Eigen::MatrixXd(R).transpose()).cwiseAbs().maxCoeff(), 0, 1e-9);
  }
}

TEST(BfsSpace, ElementFormFactorIsASquareRootOfTheElementForm) {
  for (int k : {1, 3, 128})
    for (double a : {1e-3, 1.0, 10.0}) {
      const BfsSpace V(k, 2 * k);
      const auto form = SecondOrderForm::from_a(a);
      const Eigen::Matrix<double, 16, 16> K = V.element_form(form);
      const Eigen::Matrix<double, 48, 16> B = V.element_form_factor(form);
      EXPECT_LT((B.transpose() * B - K).cwiseAbs().maxCoeff(), 1e-14 * K.cwiseAbs().maxCoeff()) << k << " " << a;
    }
  EXPECT_THROW(BfsSpace(2, 2).element_form_factor({1.0, -1.0, 1.0}), ParameterError);
}

TEST(BfsSpace, MassMatrixAndLoadAreExactForPolynomials) {
  std::mt19937 rng(3);
  const Bicubic u[3] = {random_bicubic(rng), random_bicubic(rng), random_bicubic(rng)};
  const BfsSpace V(3, 6);
  const Eigen::MatrixX3d C = interpolate_bicubics(V, u);
  const Eigen::SparseMatrix<double> M = V.assemble_mass();
  double exact = 0;
  for (int c = 0; c < 3; ++c) exact += integral_product(u[c].c, u[c].c);
  EXPECT_NEAR((C.transpose() * (M * C)).trace(), exact, 1e-12 * exact);
  // (f, u)_0 with f = the same bicubics: load vector dotted with the coefficients
  const Eigen::MatrixX3d F = V.assemble_load(
      [&](double x, double y) { return Eigen::Vector3d(u[0].d(x, y, 0, 0), u[1].d(x, y, 0, 0), u[2].d(x, y, 0, 0)); },
      4);
  EXPECT_NEAR((F.transpose() * C).trace(), exact, 1e-12 * exact);
}

/// Independent B-spline evaluation (Cox–de Boor recursion).
double bspline_basis(const std::vector<double>& t, int i, int p, double x) {
  if (p == 0) {
    const bool last = x == t.back() && t[i] < t[i + 1] && t[i + 1] == t.back();
    return ((t[i] <= x && x < t[i + 1]) || last) ? 1.0 : 0.0;
  }
  double r = 0;
  if (t[i + p] > t[i]) r += (x - t[i]) / (t[i + p] - t[i]) * bspline_basis(t, i, p - 1, x);
  if (t[i + p + 1] > t[i + 1]) r += (t[i + p + 1] - x) / (t[i + p + 1] - t[i + 1]) * bspline_basis(t, i + 1, p - 1, x);
  return r;
}

TEST(BfsSpace, BSplineFormIsTheSameSurface) {
  std::mt19937 rng(5);
  const BfsSpace V(4, 3);
  Eigen::MatrixX3d C = Eigen::MatrixX3d::Random(V.num_dofs(), 3);  // a generic C¹ field
  const auto B = V.to_bspline(C);
  const int nx = 2 * V.k() + 2, ny = 2 * V.l() + 2;
  ASSERT_EQ(static_cast<int>(B.knots_x.size()), nx + 4);
  ASSERT_EQ(static_cast<int>(B.knots_y.size()), ny + 4);
  ASSERT_EQ(B.points.rows(), nx * ny);
  std::uniform_real_distribution<double> U(0, 1);
  for (int s = 0; s < 30; ++s) {
    const double x = s == 0 ? 1.0 : U(rng), y = s == 0 ? 1.0 : U(rng);
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int I = 0; I < nx; ++I)
      for (int J = 0; J < ny; ++J)
        b += bspline_basis(B.knots_x, I, 3, x) * bspline_basis(B.knots_y, J, 3, y) *
             B.points.row(I * ny + J).transpose();
    EXPECT_LT((b - V.evaluate(C, x, y)).norm(), 1e-12);
  }
}

TEST(BfsSpace, BadArguments) {
  EXPECT_THROW(BfsSpace(0, 3), ParameterError);
  EXPECT_THROW(BfsSpace(3, BfsSpace::kMaxPartition + 1), ParameterError);
  const BfsSpace V(2, 2);
  const Eigen::MatrixX3d C = Eigen::MatrixX3d::Zero(V.num_dofs(), 3);
  EXPECT_THROW(V.evaluate(C, 1.1, 0.5), ParameterError);
  EXPECT_THROW(V.evaluate(C, std::nan(""), 0.5), ParameterError);
  EXPECT_THROW(V.evaluate(Eigen::MatrixX3d::Zero(3, 3), 0.5, 0.5), SizeError);
  EXPECT_THROW(V.assemble_load([](double, double) { return Eigen::Vector3d(1, std::nan(""), 0); }), NonFiniteError);
}

}  // namespace
}  // namespace bpde
