// Gram matrices of tensor energies against independent truths: Gauss quadrature of the integrand
// with Bernstein derivative tables, and exact integrals of polynomial patches done by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/tensor_gram.h"

namespace bpde {
namespace {

std::vector<EnergySpec> all_energies() {
  return {EnergySpec::dirichlet(),
          EnergySpec::second_order(1.5, 0.7, 0.4),
          EnergySpec::biharmonic(),
          EnergySpec::laplacian_squared(),
          EnergySpec::coons(),
          EnergySpec::modified_biharmonic(1.3),
          EnergySpec::fourth_order({1.2, -0.5, 2.5, 0.8, 0.6}),
          EnergySpec::gnorm(1.7, 0.9),
          EnergySpec::gnorm((Eigen::Matrix2d() << 1.0, 2.0, 0.5, 1.5).finished())};
}

// Q by Gauss quadrature of 1/2 Σ w (∂^a B_I ∂^b B_J + ∂^b B_I ∂^a B_J) with derivative tables.
Eigen::MatrixXd gram_by_quadrature(const std::vector<QuadraticTerm>& terms, int n, int m, double hu = 1,
                                   double hv = 1) {
  const QuadratureRule1D ru = gauss_legendre01(n + 2), rv = gauss_legendre01(m + 2);
  const int N = (n + 1) * (m + 1);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(N, N);
  for (const auto& t : terms) {
    const Eigen::MatrixXd Ua = bernstein_table(n, ru.x, t.au) / std::pow(hu, t.au);
    const Eigen::MatrixXd Ub = bernstein_table(n, ru.x, t.bu) / std::pow(hu, t.bu);
    const Eigen::MatrixXd Va = bernstein_table(m, rv.x, t.av) / std::pow(hv, t.av);
    const Eigen::MatrixXd Vb = bernstein_table(m, rv.x, t.bv) / std::pow(hv, t.bv);
    for (int g = 0; g < ru.x.size(); ++g)
      for (int h = 0; h < rv.x.size(); ++h) {
        const double wt = 0.5 * t.w * ru.w(g) * rv.w(h) * hu * hv;
        Eigen::VectorXd da(N), db(N);
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= m; ++j) {
            da(i * (m + 1) + j) = Ua(g, i) * Va(h, j);
            db(i * (m + 1) + j) = Ub(g, i) * Vb(h, j);
          }
        Q.noalias() += wt * (da * db.transpose() + db * da.transpose());
      }
  }
  return Q;
}

TEST(TensorGram, MatchesGaussQuadratureForEveryEnergy) {
  for (const auto& e : all_energies())
    for (auto [n, m] : std::vector<std::pair<int, int>>{{2, 2}, {3, 5}, {5, 2}, {6, 6}, {4, 7}}) {
      const Eigen::MatrixXd Q = tensor_gram(e, n, m);
      const Eigen::MatrixXd Qq = gram_by_quadrature(e.terms(), n, m);
      ASSERT_EQ(Q.rows(), (n + 1) * (m + 1));
      const double scale = Qq.cwiseAbs().maxCoeff();
      EXPECT_LE((Q - Qq).cwiseAbs().maxCoeff(), 1e-12 * scale) << e.name() << " n=" << n << " m=" << m;
      EXPECT_EQ((Q - Q.transpose()).cwiseAbs().maxCoeff(), 0.0);
    }
}

TEST(TensorGram, LaplacianSquaredDiffersFromBiharmonicByANullLagrangian) {
  // |Δx|^2 - (|x_uu|^2 + 2|x_uv|^2 + |x_vv|^2) = 2(<x_uu,x_vv> - |x_uv|^2) is a null Lagrangian:
  // its bilinear form vanishes whenever one argument has zero C1 boundary data, i.e. the rows of
  // the difference at the inner points (two rings in) are zero; other rows are not.
  for (auto [n, m] : std::vector<std::pair<int, int>>{{4, 4}, {5, 7}}) {
    const Eigen::MatrixXd d =
        tensor_gram(EnergySpec::laplacian_squared(), n, m) - tensor_gram(EnergySpec::biharmonic(), n, m);
    const TensorNet shape(n, m);
    for (int I : shape.free_indices(FixedSet::BoundaryAdjacent))
      EXPECT_LE(d.row(I).cwiseAbs().maxCoeff(), 1e-12 * d.cwiseAbs().maxCoeff()) << I;
    EXPECT_GT(d.cwiseAbs().maxCoeff(), 1.0);
  }
}

TEST(TensorGram, SpanScalingMatchesQuadratureOnTheRectangle) {
  const std::vector<QuadraticTerm> terms = EnergySpec::fourth_order({1.0, 0.3, 2.0, -0.4, 0.7}).terms();
  const Eigen::MatrixXd Q = tensor_gram(4, 3, terms, 0.5, 2.0);
  const Eigen::MatrixXd Qq = gram_by_quadrature(terms, 4, 3, 0.5, 2.0);
  EXPECT_LE((Q - Qq).cwiseAbs().maxCoeff(), 1e-12 * Qq.cwiseAbs().maxCoeff());
  EXPECT_THROW(tensor_gram(4, 3, terms, 0.0, 1.0), ParameterError);
  EXPECT_THROW(tensor_gram(0, 3, terms), DegreeError);
  EXPECT_THROW(tensor_gram(4, 65, terms), DegreeError);
}

// Bernstein coefficients of t^k at degree n: C(i,k)/C(n,k).
double mono(int n, int i, int k) { return binomial(i, k) / binomial(n, k); }

// Net of x = (u, v, u^a v^b) at degree (n, m).
Eigen::MatrixX3d monomial_patch(int n, int m, int a, int b) {
  Eigen::MatrixX3d P((n + 1) * (m + 1), 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) P.row(i * (m + 1) + j) << mono(n, i, 1), mono(m, j, 1), mono(n, i, a) * mono(m, j, b);
  return P;
}

TEST(TensorGram, EnergyOfKnownPolynomialPatch) {
  // x = (u, v, u^2 v): x_u = (1, 0, 2uv), x_v = (0, 1, u^2), x_uu = (0,0,2v), x_uv = (0,0,2u), x_vv = 0.
  for (auto [n, m] : std::vector<std::pair<int, int>>{{2, 1}, {3, 4}, {6, 5}}) {
    const Eigen::MatrixX3d P = monomial_patch(n, m, 2, 1);
    auto E = [&](const EnergySpec& e) { return QuadraticEnergy::tensor(e, n, m).value(P); };
    EXPECT_NEAR(E(EnergySpec::dirichlet()), 119.0 / 90.0, 1e-13);
    EXPECT_NEAR(E(EnergySpec::second_order(2.0, 3.0, 5.0)), 0.5 * (13.0 * 2 / 9 + 3.0 / 4 + 6.0 * 5 / 5), 1e-13);
    EXPECT_NEAR(E(EnergySpec::biharmonic()), 2.0, 1e-12);
    EXPECT_NEAR(E(EnergySpec::laplacian_squared()), 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(E(EnergySpec::coons()), 2.0 / 3.0, 1e-12);
    const double al = 1.3;
    EXPECT_NEAR(E(EnergySpec::modified_biharmonic(al)), 0.5 * (4.0 / 3 + 2 * al * al * 4.0 / 3), 1e-12);
    // fourth-order [a..e]: 1/2 (4a/3 + b + 4c/3) (d, e multiply zero terms here)
    EXPECT_NEAR(E(EnergySpec::fourth_order({2, 3, 5, 7, 11})), 0.5 * (8.0 / 3 + 3 + 20.0 / 3), 1e-12);
    const double rho = 1.7, t = 0.9;
    EXPECT_NEAR(E(EnergySpec::gnorm(rho, t)),
                0.5 * (4 * rho * rho / 3 + 2 * rho * std::cos(t) + 4 * (1 + rho * rho) / 3), 1e-12);
    // G = [[1, 2], [0, 1]] by rows: e1 = (1, 0), e2 = (2, 1): [1, 4, 6, 4, 5].
    EXPECT_NEAR(E(EnergySpec::gnorm((Eigen::Matrix2d() << 1, 2, 0, 1).finished())), 0.5 * (4.0 / 3 + 4 + 24.0 / 3),
                1e-12);
  }
  // x = (u, v, u v^2): x_uu = 0, x_uv = (0,0,2v), x_vv = (0,0,2u): 1/2 (4c/3 + d + 4e/3).
  for (auto [n, m] : std::vector<std::pair<int, int>>{{1, 2}, {4, 3}}) {
    const Eigen::MatrixX3d P = monomial_patch(n, m, 1, 2);
    EXPECT_NEAR(QuadraticEnergy::tensor(EnergySpec::fourth_order({2, 3, 5, 7, 11}), n, m).value(P),
                0.5 * (20.0 / 3 + 7 + 44.0 / 3), 1e-12);
    EXPECT_NEAR(QuadraticEnergy::tensor(EnergySpec::laplacian_squared(), n, m).value(P), 2.0 / 3.0, 1e-12);
  }
}

TEST(TensorGram, ScaledSpanGivesTheIntegralOverTheRectangle) {
  // x = (u, v, u^2 v) on [u0, u0+hu] x [v0, v0+hv], as a Bézier patch in local (s, t):
  // biharmonic = 1/2 ∫∫ (4 v^2 + 8 u^2) du dv.
  const double u0 = 0.5, hu = 1.5, v0 = -1.0, hv = 2.0;
  const int n = 3, m = 2;
  // power coefficients in s of u^2 = (u0 + hu s)^2 and in t of v = v0 + hv t
  Eigen::VectorXd cu = Eigen::VectorXd::Zero(n + 1), cv = Eigen::VectorXd::Zero(m + 1), lu = cu, lv = cv;
  cu << u0 * u0, 2 * u0 * hu, hu * hu, 0;
  cv << v0, hv, 0;
  lu << u0, hu, 0, 0;
  lv << v0, hv, 0;
  const Eigen::VectorXd bu = power_to_bernstein_matrix(n) * cu, bv = power_to_bernstein_matrix(m) * cv;
  const Eigen::VectorXd blu = power_to_bernstein_matrix(n) * lu, blv = power_to_bernstein_matrix(m) * lv;
  Eigen::MatrixX3d P((n + 1) * (m + 1), 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) P.row(i * (m + 1) + j) << blu(i), blv(j), bu(i) * bv(j);
  const QuadraticEnergy E(tensor_gram(n, m, EnergySpec::biharmonic().terms(), hu, hv));
  const double u1 = u0 + hu, v1 = v0 + hv;
  const double exact = 0.5 * (4 * hu * (v1 * v1 * v1 - v0 * v0 * v0) / 3 + 8 * (u1 * u1 * u1 - u0 * u0 * u0) / 3 * hv);
  EXPECT_NEAR(E.value(P), exact, 1e-12 * exact);
}

}  // namespace
}  // namespace bpde
