// Tetraharmonic surfaces (Centella et al., Theorem 1 and Annex A).
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <iostream>
#include <limits>

#include "c1_polynomials.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

using namespace testing;
using Method = TetraharmonicOptions::Method;

// An exact tetraharmonic (not triharmonic) polynomial surface of bidegree <= n, as a degree-(n,n) net.
TensorNet exact_tetraharmonic(int n) {
  const double u0 = 0.4, v0 = 0.7;
  const std::vector<std::vector<double>> U = {{0.0}, {1.0}}, V = {{0.0, 1.0}};
  if (n >= 7)
    return net_from_tables(
        n, {add(U, re(zbar_z(3, 4, u0, v0), 0.5)), add(V, add(im(zbar_z(3, 4, u0, v0), 0.5), re(zbar_z(2, 3, u0, v0)))),
            add(re(zbar_z(3, 3, u0, v0)), im(zbar_z(1, 6, u0, v0)))});
  if (n >= 6)
    return net_from_tables(n, {add(U, re(zbar_z(3, 3, u0, v0))), add(V, im(zbar_z(2, 4, u0, v0))),
                               add(re(zbar_z(3, 2, u0, v0)), im(zbar_z(1, 5, u0, v0)))});
  return net_from_tables(n, {add(U, re(zbar_z(3, 1, u0, v0))), add(V, im(zbar_z(1, 3, u0, v0))),
                             add(re(zbar_z(2, 2, u0, v0)), im(zbar_z(3, 1, u0, v0)))});
}

TensorNet scrambled_interior(const TensorNet& net) {
  TensorNet data = net;
  for (int idx : net.free_indices(FixedSet::BoundaryAdjacent))
    data.points().row(idx) = Eigen::RowVector3d(1e3, -7.0, 42.0);
  return data;
}

TEST(Tetraharmonic, ExactPolynomialIsTetraharmonic) {
  // Guard the test data itself: Δ⁴ of the exact surfaces vanishes, Δ³ does not.
  for (int n : {4, 6, 7, 10}) {
    const TensorNet x = exact_tetraharmonic(n);
    const Eigen::MatrixXd Op = tetraharmonic_operator(n);
    EXPECT_LT((Op * x.points()).cwiseAbs().maxCoeff(), 1e-9 * (Op.cwiseAbs() * x.points().cwiseAbs()).maxCoeff()) << n;
  }
}

TEST(Tetraharmonic, RecoversExactPolynomialBothMethods) {
  // Relative tolerances (max point error / max point): the explicit recursion works in the
  // power basis (docs/c1.md) and loses about a digit per degree.
  // Observed (docs/c1.md) times ~5-10; both grow with the amplification of the data (docs/c1.md).
  // lu at n = 16: the relative residual of G·data (9.9e-13 portable, 9.7e-13 with -march=native)
  // stays just under the 1e-12 above which solve_tetraharmonic refines, so the error is that of
  // the unrefined product, whose rounding depends on FMA contraction: 1.26e-9 portable, 3.85e-9
  // native (docs/performance.md, "The native build"). 6e-9 is 1.6x the larger and below twice it.
  const double tol_lu[] = {0,     0,     0,     0,     1e-15, 1e-14, 1e-14, 1e-13, 1e-13,
                           3e-13, 1e-12, 1e-12, 1e-11, 3e-11, 1e-10, 5e-10, 6e-9};
  const double tol_ex[] = {0,     0,     0,     0,     1e-14, 1e-14, 1e-14, 2e-13, 1e-12,
                           3e-12, 1e-11, 3e-11, 5e-11, 1e-10, 1e-9,  5e-9,  5e-9};
  for (int n = 4; n <= 16; ++n) {
    const TensorNet exact = exact_tetraharmonic(n);
    const TensorNet data = scrambled_interior(exact);
    for (Method m : {Method::LU, Method::Explicit}) {
      TetraharmonicOptions o;
      o.method = m;
      const auto r = solve_tetraharmonic(data, o);
      const double err = relative_difference(r.net, exact);
      std::cout << "n = " << n << (m == Method::LU ? " lu " : " explicit ") << "relative error " << err << ", residual "
                << r.summary.residual << "\n";
      EXPECT_LT(err, m == Method::LU ? tol_lu[n] : tol_ex[n]) << "n = " << n;
      for (int idx : data.fixed_indices(FixedSet::BoundaryAdjacent))
        EXPECT_EQ(r.net.points().row(idx), data.points().row(idx));
    }
  }
}

TEST(Tetraharmonic, MethodsAgreeOnGenericData) {
  for (int n : {5, 8, 11}) {
    TensorNet data(n, n);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        data.set_point(i, j,
                       Eigen::Vector3d(i / double(n), j / double(n), std::sin(3.0 * i / n) * std::cos(2.0 * j / n)));
    TetraharmonicOptions o;
    const auto lu = solve_tetraharmonic(data, o);
    o.method = Method::Explicit;
    const auto ex = solve_tetraharmonic(data, o);
    EXPECT_TRUE(lu.summary.converged) << lu.summary.message;
    EXPECT_LT(lu.summary.residual, 1e-13);
    EXPECT_LT(relative_difference(ex.net, lu.net), 1e-10) << n;
    // Δ⁴x = 0 checked with derivatives of the result at sample points (eq. (6)), relative to a
    // bound of the rounding in the derivative nets: n!/(n-du)! n!/(n-dv)! 2^(du+dv) max|P|.
    const double pmax = lu.net.points().cwiseAbs().maxCoeff();
    for (double u : {0.2, 0.55})
      for (double v : {0.35, 0.9}) {
        Eigen::Vector3d s = Eigen::Vector3d::Zero();
        double bound = 0.0;
        const int dd[5][2] = {{8, 0}, {6, 2}, {4, 4}, {2, 6}, {0, 8}};
        const double c[5] = {1, 4, 6, 4, 1};
        for (int t = 0; t < 5; ++t) {
          if (dd[t][0] > n || dd[t][1] > n) continue;
          s += c[t] * lu.net.derivative(u, v, dd[t][0], dd[t][1]);
          bound +=
              c[t] * factorial(n) / factorial(n - dd[t][0]) * factorial(n) / factorial(n - dd[t][1]) * 256.0 * pmax;
        }
        EXPECT_LT(s.cwiseAbs().maxCoeff(), 1e-13 * bound) << n;
      }
  }
}

TEST(Tetraharmonic, LuConvergesAtDegree20WhereExplicitDoesNot) {
  const int n = 20;
  TensorNet data(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      data.set_point(i, j, Eigen::Vector3d(i / double(n), j / double(n), std::sin(3.0 * i / n)));
  const auto lu = solve_tetraharmonic(data);
  EXPECT_TRUE(lu.summary.converged) << lu.summary.message;
  EXPECT_EQ(lu.summary.status, Status::Converged);
  EXPECT_LT(lu.summary.residual, 1e-15);
  TetraharmonicOptions o;
  o.method = Method::Explicit;
  const auto ex = solve_tetraharmonic(data, o);
  EXPECT_FALSE(ex.summary.converged);  // the power-basis recursion is honest about its accuracy
  EXPECT_EQ(ex.summary.status, Status::NumericalLimit) << ex.summary.message;
  EXPECT_NE(ex.summary.message.find("lu"), std::string::npos);  // the message suggests the remedy
}

TEST(Tetraharmonic, SolutionSpaceHasDimension8nMinus8) {
  for (int n = 3; n <= 14; ++n) {
    const Eigen::MatrixXd Op = tetraharmonic_operator(n);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Op);
    const Eigen::VectorXd s = svd.singularValues();
    int rank = 0;
    while (rank < s.size() && s(rank) > 1e-10 * s(0)) ++rank;
    EXPECT_EQ(Op.cols() - rank, 8 * n - 8) << "n = " << n;
    if (rank > 0 && rank < s.size()) {
      EXPECT_GT(s(rank - 1) / std::max(s(rank), 1e-300), 1e5) << "no clear gap at n = " << n;
    }
    // Independent count in the factorial power basis, eq. (7), whose coefficients are 1 4 6 4 1:
    // equations at every (i, j) with i, j >= 0 (entries beyond n are zero).
    const int N = (n + 1) * (n + 1);
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(N, N);
    const double c[5] = {1, 4, 6, 4, 1};
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int t = 0; t < 5; ++t) {
          const int a = i + 8 - 2 * t, b = j + 2 * t;
          if (a <= n && b <= n) E(i * (n + 1) + j, a * (n + 1) + b) = c[t];
        }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(E);
    EXPECT_EQ(N - lu.rank(), 8 * n - 8) << "power-basis count, n = " << n;
    // Uniqueness (Theorem 1): the operator has full column rank on the interior points.
    if (n >= 4) {
      const TensorNet shape(n, n);
      const auto interior = shape.free_indices(FixedSet::BoundaryAdjacent);
      Eigen::MatrixXd A(Op.rows(), static_cast<Eigen::Index>(interior.size()));
      for (size_t k = 0; k < interior.size(); ++k) A.col(static_cast<Eigen::Index>(k)) = Op.col(interior[k]);
      Eigen::JacobiSVD<Eigen::MatrixXd> sa(A);
      EXPECT_GT(sa.singularValues().minCoeff(), 1e-10 * sa.singularValues().maxCoeff()) << n;
    }
  }
}

TEST(Tetraharmonic, Lemma2Determinant) {
  for (int k = 1; k <= 14; ++k) {
    const double det = tetraharmonic_detail::lemma2_matrix(k).determinant();
    EXPECT_NEAR(det, tetraharmonic_detail::lemma2_determinant(k), 1e-9 * det) << "k = " << k;
  }
  EXPECT_DOUBLE_EQ(tetraharmonic_detail::lemma2_determinant(1), 6.0);   // det [6]
  EXPECT_DOUBLE_EQ(tetraharmonic_detail::lemma2_determinant(2), 20.0);  // det [[6,4],[4,6]]
}

// Lemma 1, eq. (8): on the factorial-power coefficients of a tetraharmonic polynomial, rows 2k
// and 2k+1 (k >= 4) follow from the first eight rows. Exact coefficient tables of bidegree 12.
TEST(Tetraharmonic, Lemma1ClosedForm) {
  const int n = 12;
  const auto p = add(add(re(zbar_z(3, 9, 0.2, -0.1)), im(zbar_z(2, 10, 0.2, -0.1), 0.7)),
                     add(re(zbar_z(1, 11, 0.2, -0.1), -0.3), im(zbar_z(3, 8, 0.2, -0.1))));
  auto A = [&](int i, int j) -> double {
    if (i < 0 || j < 0 || i >= static_cast<int>(p.size()) || j >= static_cast<int>(p[0].size())) return 0.0;
    return factorial(i) * factorial(j) * p[static_cast<size_t>(i)][static_cast<size_t>(j)];
  };
  int nonzero = 0;
  for (int k = 4; 2 * k + 1 <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int odd = 0; odd <= 1; ++odd) {
        const double K = k;
        const double s = ((k + 1) % 2 == 0 ? 1.0 : -1.0) / 6.0 * (K - 3) * (K - 2) * (K - 1) * K;
        const double t[4] = {s * A(6 + odd, 2 * k + j - 6) / (K - 3), s * 3.0 * A(4 + odd, 2 * k + j - 4) / (K - 2),
                             s * 3.0 * A(2 + odd, 2 * k + j - 2) / (K - 1), s * A(odd, 2 * k + j) / K};
        const double lhs = A(2 * k + odd, j), scale = std::abs(t[0]) + std::abs(t[1]) + std::abs(t[2]) + std::abs(t[3]);
        EXPECT_NEAR(lhs, t[0] + t[1] + t[2] + t[3], 1e-12 * scale) << k << " " << j << " " << odd;
        if (std::abs(lhs) > 1e-6 * scale && scale > 0) ++nonzero;
      }
  EXPECT_GT(nonzero, 5);  // the identity is exercised on non-zero coefficients
}

TEST(Tetraharmonic, BadInput) {
  EXPECT_THROW(solve_tetraharmonic(TensorNet(3, 3)), DegreeError);
  EXPECT_THROW(solve_tetraharmonic(TensorNet(5, 6)), DegreeError);
  TensorNet data(6, 6);
  data.points()(data.index(0, 3), 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solve_tetraharmonic(data), NonFiniteError);
  TetraharmonicOptions o;
  o.method = Method::Explicit;
  EXPECT_THROW(solve_tetraharmonic(data, o), NonFiniteError);
  // A non-finite interior point is not data: it is ignored.
  TensorNet ok(6, 6);
  ok.points()(ok.index(3, 3), 0) = std::numeric_limits<double>::infinity();
  EXPECT_NO_THROW(solve_tetraharmonic(ok));
  EXPECT_THROW(parse_tetraharmonic_method("gauss"), ParameterError);
  EXPECT_EQ(parse_tetraharmonic_method("explicit"), Method::Explicit);
}

}  // namespace
}  // namespace bpde
