// core/symmetric_factor: the positive-definite verdict on known SPD, indefinite, singular and
// nearly semidefinite matrices, the condition estimate, and the solves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bezierpde/core/symmetric_factor.h"

using namespace bpde;

namespace {

// The 1-D Dirichlet Laplacian tridiag(-1, 2, -1): SPD, eigenvalues 2 - 2 cos(k pi / (n+1)).
Eigen::MatrixXd laplacian(int n) {
  Eigen::MatrixXd A = 2.0 * Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) A(i, i + 1) = A(i + 1, i) = -1.0;
  return A;
}

TEST(SymmetricFactor, PositiveDefinite) {
  const int n = 12;
  const Eigen::MatrixXd A = laplacian(n);
  const SymmetricFactor<> f(A);
  EXPECT_TRUE(f.cholesky());
  EXPECT_TRUE(f.positive_definite());
  // 1-norm reciprocal condition number of this matrix: |A|_1 = 4 and, with
  // A^-1(i,j) = min(i,j) (n+1-max(i,j)) / (n+1), |A^-1|_1 = max_j j (n+1-j) / 2 (= 21 at n = 12).
  // The estimator bounds |A^-1|_1 from below, so rcond is >= the truth, and within a small factor.
  double inv_norm = 0;
  for (int j = 1; j <= n; ++j) inv_norm = std::max(inv_norm, j * (n + 1.0 - j) / 2.0);
  const double truth = 1.0 / (4.0 * inv_norm);
  EXPECT_GE(f.rcond(), truth * (1 - 1e-12));
  EXPECT_LE(f.rcond(), 3.0 * truth);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  EXPECT_LE((f.solve(A * x) - x).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LE((f.matrixL() * f.matrixL().transpose() - A).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(f.min_pivot(), (f.matrixL().diagonal().cwiseAbs2().minCoeff()), 0.0);
}

TEST(SymmetricFactor, Indefinite) {
  Eigen::MatrixXd A = laplacian(5);
  A(2, 2) = -3.0;
  const SymmetricFactor<> f(A);
  EXPECT_FALSE(f.cholesky());
  EXPECT_FALSE(f.positive_definite());
  EXPECT_EQ(f.rcond(), 0.0);
  EXPECT_LT(f.min_pivot(), -0.1);
  // The LDL^T still solves the (regular) system.
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(5, 1.0, 3.0);
  EXPECT_LE((f.solve(A * x) - x).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SymmetricFactor, SingularSemidefiniteCountsAsPositiveWithinTheTolerance) {
  // [[1,1],[1,1]]: the Cholesky fails on the zero pivot; the LDL^T pivots are 1 and 0, which the
  // verdict accepts (rounding-level pivots of a semidefinite Gram), unless the tolerance is < 0.
  Eigen::MatrixXd A(2, 2);
  A << 1, 1, 1, 1;
  const SymmetricFactor<> f(A);
  EXPECT_FALSE(f.cholesky());
  EXPECT_TRUE(f.positive_definite());
  EXPECT_EQ(f.min_pivot(), 0.0);
  // A pivot of -1e-12 relative passes the default 1e-10 and fails a zero tolerance.
  A(1, 1) = 1.0 - 1e-12;
  EXPECT_TRUE(SymmetricFactor<>(A).positive_definite());
  EXPECT_FALSE(SymmetricFactor<>(A, 0.0).positive_definite());
  // A pivot of -1e-8 relative fails the default.
  A(1, 1) = 1.0 - 1e-8;
  EXPECT_FALSE(SymmetricFactor<>(A).positive_definite());
  // The zero matrix has no positive pivot: not positive definite.
  EXPECT_FALSE(SymmetricFactor<>(Eigen::MatrixXd::Zero(3, 3)).positive_definite());
}

TEST(SymmetricFactor, NumericallySingularShowsInTheConditionEstimate) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(2, 2) = 1e-17;
  const SymmetricFactor<> f(A);
  EXPECT_TRUE(f.cholesky());
  EXPECT_TRUE(f.positive_definite());
  EXPECT_LT(f.rcond(), 1e-13);
  EXPECT_GT(f.rcond(), 0.0);
  EXPECT_NEAR(f.min_pivot(), 1e-17, 1e-30);
}

TEST(SymmetricFactor, NonFiniteIsNotACholesky) {
  Eigen::MatrixXd A = laplacian(3);
  A(1, 1) = std::numeric_limits<double>::quiet_NaN();
  const SymmetricFactor<> f(A);
  EXPECT_FALSE(f.cholesky());
  EXPECT_FALSE(f.positive_definite());
}

TEST(SymmetricFactor, LongDoubleAndEmpty) {
  const Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> A = laplacian(6).cast<long double>();
  const SymmetricFactor<long double> f(A);
  EXPECT_TRUE(f.cholesky());
  const Eigen::Matrix<long double, Eigen::Dynamic, 1> x = Eigen::Matrix<long double, Eigen::Dynamic, 1>::Ones(6);
  EXPECT_LE(static_cast<double>((f.solve(A * x) - x).cwiseAbs().maxCoeff()), 1e-17);
  const SymmetricFactor<> e{Eigen::MatrixXd(0, 0)};
  EXPECT_TRUE(e.cholesky());
  EXPECT_TRUE(e.positive_definite());
  EXPECT_EQ(e.min_pivot(), 0.0);
}

}  // namespace
