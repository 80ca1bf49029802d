// core/bernstein_ops: derivative, elevation and derivative-at-degree operators in double, long
// double and binary128 against exact polynomials (monomials t^a, whose Bernstein coefficients and
// derivatives are known in closed form) and against de Casteljau evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"

using namespace bpde;

namespace {

// Bernstein coefficients at degree n of c * t^a: c C(i, a) / C(n, a), in binary128.
std::vector<quad> monomial(int n, int a, quad c = 1) {
  std::vector<quad> p(static_cast<size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) p[static_cast<size_t>(i)] = c * binomial<quad>(i, a) / binomial<quad>(n, a);
  return p;
}

quad falling(int a, int d) {
  quad s = 1;
  for (int k = 0; k < d; ++k) s *= a - k;
  return s;
}

template <class T>
double max_rel_error(const std::vector<T>& rm, int rows, int cols, const std::vector<quad>& x,
                     const std::vector<quad>& want) {
  // Error of (rm x) (summed in binary128) relative to the size of the terms, sum_c |rm(r,c)| |x(c)|:
  // what the rounding of the entries of rm can cause.
  double worst = 0;
  for (int r = 0; r < rows; ++r) {
    quad acc = 0, mag = 0;
    for (int c = 0; c < cols; ++c) {
      const quad a = static_cast<quad>(rm[static_cast<size_t>(r * cols + c)]) * x[static_cast<size_t>(c)];
      acc += a;
      mag += a < 0 ? -a : a;
    }
    const double e = std::abs(static_cast<double>(acc - want[static_cast<size_t>(r)]));
    worst = std::max(worst, mag > 0 ? e / static_cast<double>(mag) : e);
  }
  return worst;
}

template <class T>
void check_derivative_at_degree(double tol) {
  for (int n : {1, 4, 9, 16, 24})
    for (int d = 0; d <= std::min(n, 8); ++d)
      for (int a = d; a <= n; a += 3) {
        // d-th derivative of t^a is a!/(a-d)! t^(a-d), written at degree n.
        const std::vector<T> Tnd = derivative_at_degree_rm<T>(n, d);
        const double e = max_rel_error(Tnd, n + 1, n + 1, monomial(n, a), monomial(n, a - d, falling(a, d)));
        EXPECT_LE(e, tol) << "n " << n << " d " << d << " a " << a;
      }
}

TEST(BernsteinOps, DerivativeAtDegreeOnMonomials) {
  check_derivative_at_degree<double>(1e-14);
  check_derivative_at_degree<long double>(1e-17);
  check_derivative_at_degree<quad>(1e-31);
}

TEST(BernsteinOps, DerivativeOfTooHighOrderIsZero) {
  for (const auto& v : derivative_at_degree_rm<quad>(3, 4)) EXPECT_TRUE(v == 0);
  EXPECT_EQ(derivative_at_degree_matrix<long double>(5, 6).cwiseAbs().maxCoeff(), 0.0L);
  EXPECT_EQ(derivative_at_degree_matrix<double>(5, 6).rows(), 6);
  EXPECT_EQ(derivative_at_degree_matrix<double>(5, 6).cwiseAbs().maxCoeff(), 0.0);
}

TEST(BernsteinOps, DerivativeEntriesAreExactIntegers) {
  // D_{n,d}(j, j+k) = (-1)^(d-k) C(d,k) n (n-1) .. (n-d+1), exact in double for n <= 64, d <= 8.
  for (int n : {8, 23, 40, 64})
    for (int d = 0; d <= 8; ++d) {
      std::int64_t s = 1;
      for (int k = 0; k < d; ++k) s *= n - k;
      const std::vector<double> D = derivative_operator_rm<double>(n, d);
      for (int k = 0; k <= d; ++k) {
        std::int64_t c = 1;  // C(d, k)
        for (int i = 1; i <= k; ++i) c = c * (d - k + i) / i;
        const std::int64_t want = ((d - k) % 2 ? -1 : 1) * c * s;
        EXPECT_EQ(D[static_cast<size_t>(k)], static_cast<double>(want)) << n << ' ' << d << ' ' << k;
      }
    }
}

TEST(BernsteinOps, EigenFormsAreTheSameEntries) {
  for (int n : {2, 7, 30}) {
    for (int d = 0; d <= std::min(n, 4); ++d) {
      EXPECT_EQ(bernstein_derivative_operator(n, d),
                rm_to_matrix<double>(derivative_operator_rm<double>(n, d), n - d + 1, n + 1));
      EXPECT_EQ(derivative_at_degree_matrix<double>(n, d),
                rm_to_matrix<double>(derivative_at_degree_rm<double>(n, d), n + 1, n + 1));
    }
    EXPECT_EQ(bernstein_elevation_operator(n, 3),
              rm_to_matrix<double>(elevation_operator_rm<double>(n, 3), n + 4, n + 1));
  }
}

TEST(BernsteinOps, ElevationKeepsThePolynomial) {
  // elevate(p, r) and E_{n,r} against de Casteljau values of the same polynomial.
  auto de_casteljau = [](std::vector<long double> b, long double t) {
    for (size_t m = b.size(); m-- > 1;)
      for (size_t i = 0; i < m; ++i) b[i] = (1 - t) * b[i] + t * b[i + 1];
    return b[0];
  };
  for (int n : {0, 1, 5, 13})
    for (int r : {0, 1, 4, 11}) {
      VecLD p(n + 1);
      for (int i = 0; i <= n; ++i) p(i) = std::sin(1.0L + 0.7L * i) * (i % 3 ? 1 : -2);
      const VecLD g = elevate(p, r);
      ASSERT_EQ(g.size(), n + r + 1);
      const std::vector<long double> E = elevation_operator_rm<long double>(n, r);
      std::vector<long double> pv(p.data(), p.data() + p.size()), gv(g.data(), g.data() + g.size()),
          ev(static_cast<size_t>(n + r + 1), 0);
      for (int j = 0; j <= n + r; ++j)
        for (int i = 0; i <= n; ++i) ev[static_cast<size_t>(j)] += E[static_cast<size_t>(j * (n + 1) + i)] * p(i);
      for (long double t : {0.0L, 0.21L, 0.5L, 0.77L, 1.0L}) {
        const long double want = de_casteljau(pv, t);
        EXPECT_NEAR(static_cast<double>(de_casteljau(gv, t)), static_cast<double>(want), 1e-17);
        EXPECT_NEAR(static_cast<double>(de_casteljau(ev, t)), static_cast<double>(want), 1e-17);
      }
    }
  // Elevating a monomial's coefficients gives the monomial's coefficients at the higher degree.
  const std::vector<quad> m5 = monomial(5, 2), m9 = monomial(9, 2);
  const std::vector<quad> E = elevation_operator_rm<quad>(5, 4);
  for (int j = 0; j <= 9; ++j) {
    quad acc = 0;
    for (int i = 0; i <= 5; ++i) acc += E[static_cast<size_t>(j * 6 + i)] * m5[static_cast<size_t>(i)];
    EXPECT_LE(std::abs(static_cast<double>(acc - m9[static_cast<size_t>(j)])), 1e-32);
  }
}

TEST(BernsteinOps, DerivativeAgainstFiniteDifferences) {
  // Double derivative_at_degree_matrix(n, 1) against central differences of the polynomial's values.
  const int n = 7;
  Eigen::VectorXd p(n + 1);
  for (int i = 0; i <= n; ++i) p(i) = std::cos(0.3 * i * i);
  const Eigen::VectorXd dp = derivative_at_degree_matrix<double>(n, 1) * p;
  std::vector<double> b(n + 1);
  auto value = [&](const Eigen::VectorXd& c, double t) {
    bernstein_values(n, t, b.data());
    double v = 0;
    for (int i = 0; i <= n; ++i) v += c(i) * b[static_cast<size_t>(i)];
    return v;
  };
  const double h = 1e-5;
  for (double t : {0.1, 0.4, 0.66, 0.9}) {
    const double fd = (value(p, t + h) - value(p, t - h)) / (2 * h);
    EXPECT_NEAR(value(dp, t), fd, 1e-7 * (1 + std::abs(fd)));
  }
}

TEST(BernsteinOps, Errors) {
  EXPECT_THROW(derivative_operator_rm<double>(3, 4), DegreeError);
  EXPECT_THROW(derivative_operator_rm<quad>(3, -1), DegreeError);
  EXPECT_THROW(elevation_operator_rm<long double>(-1, 2), DegreeError);
  EXPECT_THROW(derivative_at_degree_rm<double>(2, -1), DegreeError);
  EXPECT_THROW(elevate(VecLD(VecLD::Ones(3)), -1), DegreeError);
}

}  // namespace
