// core/bernstein: tables, operators and exact integrals against independent computations.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <utility>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"

using namespace bpde;

TEST(Bernstein, BinomialAndFactorial) {
  EXPECT_EQ(binomial(10, 3), 120.0);
  EXPECT_EQ(binomial(5, 6), 0.0);
  EXPECT_EQ(binomial(56, 28), 7648690600760440.0);
  EXPECT_EQ(factorial(10), 3628800.0);
}

TEST(Bernstein, ValuesMatchClosedFormAndSumToOne) {
  for (int n : {1, 2, 7, 25, 64}) {
    std::vector<double> b(n + 1);
    for (double t : {0.0, 0.13, 0.5, 0.91, 1.0}) {
      bernstein_values(n, t, b.data());
      double sum = 0;
      for (int i = 0; i <= n; ++i) {
        const double direct = binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
        EXPECT_NEAR(b[i], direct, 1e-14 * (1 + direct));
        sum += b[i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
}

TEST(Bernstein, TableMatchesTheRecurrence) {
  // bernstein_table (product form, vectorised over points) against bernstein_values (the
  // all-positive de Casteljau recurrence), entry by entry, relative.
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(37, 0.0, 1.0);
  for (int n : {1, 4, 20, 64}) {
    const Eigen::MatrixXd B = bernstein_table(n, t);
    std::vector<double> b(static_cast<size_t>(n + 1));
    for (Eigen::Index r = 0; r < t.size(); ++r) {
      bernstein_values(n, t(r), b.data());
      for (int i = 0; i <= n; ++i)
        EXPECT_NEAR(B(r, i), b[static_cast<size_t>(i)], 4e-16 * (n + 2) * b[static_cast<size_t>(i)] + 1e-300);
    }
  }
}

TEST(Bernstein, DerivativeTableMatchesFiniteDifferences) {
  const int n = 9;
  Eigen::VectorXd t(3);
  t << 0.2, 0.5, 0.77;
  const double h = 1e-5;
  Eigen::VectorXd tp = t.array() + h, tm = t.array() - h;
  const Eigen::MatrixXd d1 = bernstein_table(n, t, 1);
  const Eigen::MatrixXd fd = (bernstein_table(n, tp) - bernstein_table(n, tm)) / (2 * h);
  EXPECT_LT((d1 - fd).cwiseAbs().maxCoeff(), 1e-6);
  const Eigen::MatrixXd d2 = bernstein_table(n, t, 2);
  const Eigen::MatrixXd fd2 = (bernstein_table(n, tp, 1) - bernstein_table(n, tm, 1)) / (2 * h);
  EXPECT_LT((d2 - fd2).cwiseAbs().maxCoeff(), 1e-4);
}

TEST(Bernstein, ProductIntegralsMatchQuadrature) {
  const auto q = gauss_legendre01(20);
  for (auto [n, m] : {std::pair{3, 5}, std::pair{7, 7}, std::pair{12, 4}}) {
    const Eigen::MatrixXd G = bernstein_product_integrals(n, m);
    const Eigen::MatrixXd Bn = bernstein_table(n, q.x), Bm = bernstein_table(m, q.x);
    const Eigen::MatrixXd Gq = Bn.transpose() * q.w.asDiagonal() * Bm;
    EXPECT_LT((G - Gq).cwiseAbs().maxCoeff(), 1e-15);
    // int B_i^n = 1/(n+1): a wrong normalisation would show here
    EXPECT_NEAR(G.sum(), 1.0, 1e-14);
  }
}

TEST(Bernstein, DerivativeIntegralsMatchQuadrature) {
  const auto q = gauss_legendre01(20);
  const int n = 8;
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 2; ++b) {
      const Eigen::MatrixXd K = bernstein_derivative_integrals(n, a, b);
      const Eigen::MatrixXd Kq = bernstein_table(n, q.x, a).transpose() * q.w.asDiagonal() * bernstein_table(n, q.x, b);
      EXPECT_LT((K - Kq).cwiseAbs().maxCoeff(), 1e-10 * (1 + Kq.cwiseAbs().maxCoeff()));
    }
}

TEST(Bernstein, ElevationPreservesValues) {
  const int n = 6, r = 5;
  Eigen::VectorXd p = Eigen::VectorXd::LinSpaced(n + 1, -1, 2).array().square();
  const Eigen::VectorXd pe = bernstein_elevation_operator(n, r) * p;
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(11, 0, 1);
  EXPECT_LT((bernstein_table(n, t) * p - bernstein_table(n + r, t) * pe).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Bernstein, PowerBasisInverse) {
  for (int n : {1, 4, 10}) {
    const Eigen::MatrixXd I = bernstein_to_power_matrix(n) * power_to_bernstein_matrix(n);
    EXPECT_LT((I - Eigen::MatrixXd::Identity(n + 1, n + 1)).cwiseAbs().maxCoeff(), 1e-9);
  }
  // B_1^2 = 2t - 2t^2
  const Eigen::MatrixXd M = bernstein_to_power_matrix(2);
  EXPECT_EQ(M(0, 1), 0.0);
  EXPECT_EQ(M(1, 1), 2.0);
  EXPECT_EQ(M(2, 1), -2.0);
}

TEST(Quadrature, GaussExactness) {
  const auto g = gauss_legendre01(5);  // exact to degree 9
  double s = 0;
  for (int i = 0; i < 5; ++i) s += g.w(i) * std::pow(g.x(i), 9);
  EXPECT_NEAR(s, 0.1, 1e-15);
  const auto t = gauss_triangle(6);  // exact to total degree 10
  double a = 0, m = 0;
  for (Eigen::Index i = 0; i < t.w.size(); ++i) {
    a += t.w(i);
    m += t.w(i) * std::pow(t.uv(i, 0), 4) * std::pow(t.uv(i, 1), 3);  // 4! 3! / 9! = 1/2520
  }
  EXPECT_NEAR(a, 0.5, 1e-15);
  EXPECT_NEAR(m, 1.0 / 2520, 1e-17);
  EXPECT_THROW(gauss_legendre01(0), ParameterError);
}

// The corner-collapsed rules (core/quadrature.h) against exact monomial integrals:
// ∫_T u^a v^b = a! b! / (a + b + 2)! on the triangle and 1 / ((a + 1)(b + 1)) on the square, for the
// plain, the graded (s = σ³) and the geometric (10 levels) radial coordinate. A polynomial of total
// degree d pulls back to degree ≤ d + 1 in s (the Jacobian) and ≤ d in t, so q = 6 (exact to 11)
// covers d ≤ 9 when plain, and on each geometric piece; 6(L + 1)q² and 8(L + 1)q² nodes.
TEST(Quadrature, CornerCollapsedRulesIntegrateMonomialsExactly) {
  auto fact = [](int k) { return std::tgamma(k + 1.0); };
  for (const auto& [grading, L] : {std::pair{1, 0}, std::pair{3, 0}, std::pair{1, 10}}) {
    const int q = grading == 1 ? 6 : 16;  // s = σ³ triples the degree in σ
    const QuadratureRuleTriangle t = corner_collapsed_triangle_rule(q, grading, L);
    const QuadratureRuleTriangle sq = corner_collapsed_square_rule(q, grading, L);
    EXPECT_EQ(t.w.size(), 6 * (L + 1) * q * q);
    EXPECT_EQ(sq.w.size(), 8 * (L + 1) * q * q);
    for (int a = 0; a <= 5; ++a)
      for (int b = 0; a + b <= 8; ++b) {
        double it = 0, is = 0;
        for (Eigen::Index i = 0; i < t.w.size(); ++i) it += t.w(i) * std::pow(t.uv(i, 0), a) * std::pow(t.uv(i, 1), b);
        for (Eigen::Index i = 0; i < sq.w.size(); ++i)
          is += sq.w(i) * std::pow(sq.uv(i, 0), a) * std::pow(sq.uv(i, 1), b);
        EXPECT_NEAR(it, fact(a) * fact(b) / fact(a + b + 2), 1e-15)
            << a << " " << b << " grading " << grading << " L " << L;
        EXPECT_NEAR(is, 1.0 / ((a + 1) * (b + 1)), 1e-14) << a << " " << b << " grading " << grading << " L " << L;
      }
    for (Eigen::Index i = 0; i < t.w.size(); ++i) {
      EXPECT_GT(t.w(i), 0.0);
      EXPECT_GE(t.uv(i, 0), 0.0);
      EXPECT_GE(t.uv(i, 1), 0.0);
      EXPECT_LE(t.uv(i, 0) + t.uv(i, 1), 1.0 + 1e-15);
    }
  }
  EXPECT_THROW(corner_collapsed_triangle_rule(0), ParameterError);
  EXPECT_THROW(corner_collapsed_square_rule(201), ParameterError);
  EXPECT_THROW(corner_collapsed_triangle_rule(5, 5), ParameterError);
  EXPECT_THROW(corner_collapsed_triangle_rule(6, 3, 2), ParameterError);  // levels take grading 1
  EXPECT_THROW(corner_collapsed_square_rule(6, 1, -1), ParameterError);
  EXPECT_THROW(corner_collapsed_square_rule(6, 1, kMaxGeometricLevels + 1), ParameterError);
}

// What the geometric rules are for: an integrand with a branch point close to, but not at, a
// corner (|x_u ∧ x_v| = |N0 + a u + b v| where a corner nearly degenerates and the linear part
// nearly cancels N0 at a point p off the corner: in polar coordinates at the corner the branch
// point is at radius ~|p| off the real axis by ~ε). f = √(ε² + |x − p|²), p = (c, 0) on the edge
// v = 0, c = 1e-3, ε = 1e-4, against the truth from polar coordinates at p: T is the two triangles
// with apex p over the edges (1,0)-(0,1) and (0,1)-(0,0), and on each ∫ f = ∫ F(R(φ)) dφ with
// F(R) = ((ε² + R²)^{3/2} − ε³)/3 and R(φ) = d / cos(φ − φ_n) the distance to the opposite edge
// (analytic in φ, taken by adaptive Gauss). Measured: the graded q = 64 rule (24 576 nodes) 1.3e-12,
// q = 86 5.9e-13, the plain q = 64 1.9e-11; the geometric q = 12 rule (9 504 nodes) 2.9e-15.
TEST(Quadrature, GeometricCornerRuleResolvesABranchPointNearACorner) {
  const double c = 1e-3, eps = 1e-4;
  const Eigen::Vector2d p(c, 0);
  const QuadratureRule1D g = gauss_legendre01(20);
  // Adaptive Gauss in φ (20 points against 2 × 20 on the halves, to 1e-17): R(φ) has a pole just
  // outside the range of the second triangle, where its edge is seen at a grazing angle.
  std::function<double(const std::function<double(double)>&, double, double, int)> adapt =
      [&](const std::function<double(double)>& f, double lo, double hi, int depth) {
        auto gauss = [&](double x0, double x1) {
          double v = 0;
          for (Eigen::Index i = 0; i < g.x.size(); ++i) v += g.w(i) * (x1 - x0) * f(x0 + (x1 - x0) * g.x(i));
          return v;
        };
        const double mid = (lo + hi) / 2, whole = gauss(lo, hi), halves = gauss(lo, mid) + gauss(mid, hi);
        if (std::abs(whole - halves) <= 1e-17 || depth >= 40) return halves;
        return adapt(f, lo, mid, depth + 1) + adapt(f, mid, hi, depth + 1);
      };
  double truth = 0;
  for (const auto& [A, B] : {std::pair{Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)},
                             std::pair{Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 0)}}) {
    const Eigen::Vector2d e = (B - A).normalized();
    Eigen::Vector2d nrm(e(1), -e(0));
    if ((A - p).dot(nrm) < 0) nrm = -nrm;
    const double d = (A - p).dot(nrm), phin = std::atan2(nrm(1), nrm(0));
    const double f0 = std::atan2((A - p)(1), (A - p)(0)), f1 = std::atan2((B - p)(1), (B - p)(0));
    truth += adapt(
        [&](double phi) {
          const double R = d / std::cos(phi - phin);
          return (std::pow(eps * eps + R * R, 1.5) - eps * eps * eps) / 3;
        },
        std::min(f0, f1), std::max(f0, f1), 0);
  }
  auto error = [&](const QuadratureRuleTriangle& r) {
    double v = 0;
    for (Eigen::Index i = 0; i < r.w.size(); ++i)
      v += r.w(i) * std::sqrt(eps * eps + (r.uv.row(i).transpose() - p).squaredNorm());
    return std::abs(v - truth) / truth;
  };
  EXPECT_LT(error(corner_collapsed_triangle_rule(40, 1, 20)), 1e-13);  // the truth, checked
  const double graded = error(corner_collapsed_triangle_rule(64, 3));
  const double geometric = error(corner_collapsed_triangle_rule(12, 1, 10));
  EXPECT_GT(graded, 1e-12);
  EXPECT_LT(geometric, 1e-13);
}
