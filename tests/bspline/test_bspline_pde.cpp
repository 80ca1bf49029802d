// solvers/bspline/bspline_pde: ranks (Sun–Zhu Examples 1-2, docs/errata.md), exact polynomial solutions on
// single- and multi-span nets, incompatible data, degenerate operators, bad input.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>

#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"
#include "tests/bspline/helpers.h"

using namespace bpde;
using namespace bpde::testing;

namespace {

int rank_of(const Eigen::MatrixXd& A) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A);
  const Eigen::VectorXd s = svd.singularValues();
  int r = 0;
  for (int k = 0; k < s.size(); ++k) r += s(k) > 1e-10 * s(0);
  return r;
}

double max_point_error(const BSplineNet& a, const BSplineNet& b) {
  return (a.points() - b.points()).cwiseAbs().maxCoeff() / (1 + b.points().cwiseAbs().maxCoeff());
}

BSplineNet blank_free(BSplineNet net, const std::vector<int>& free) {
  for (int idx : free) net.points().row(idx).setZero();
  return net;
}

// A polynomial solution of the 4th-order operator [A..E] of bidegree <= (k, k): real and imaginary
// parts of (u + lam v)^k for the characteristic roots lam, plus a cubic (any cubic solves it).
Field fourth_order_solution(const std::array<double, 5>& c, int k) {
  const auto r = roots({c[0], c[1], c[2], c[3], c[4]});
  return [r, k](double u, double v) {
    return Eigen::Vector3d(re_power(r[0], k, u, v) + 0.5 * u * u * v,
                           im_power(r[0], k, u, v) + re_power(r[2], k - 1, u, v),
                           im_power(r[2], k, u, v) + v * v * v - u);
  };
}

}  // namespace

TEST(BSplinePde, Example1HasRank9AndASevenDimensionalSolutionSpace) {
  // Sun–Zhu Example 1: (1,-2,1), bicubic, 4 x 4 points, uniform knots 0..7, span [3,4].
  const std::vector<double> K = uniform(8);
  const EnergySpec op = EnergySpec::second_order(1, -2, 1);
  const Eigen::MatrixXd A = bspline_pde_equations(3, 3, K, K, op);
  EXPECT_EQ(rank_of(A), 9);  // not 12 as printed (docs/errata.md)
  // The null space is exactly {f(u+v) + (u-v) g(u+v)}, deg f <= 3, deg g <= 2: 7 independent nets.
  Eigen::MatrixXd sols(16, 7);
  for (int k = 0; k < 7; ++k) {
    const Field f = [k](double u, double v) {
      const double s = u + v, d = u - v;
      const double val = k < 4 ? std::pow(s, k) : d * std::pow(s, k - 4);
      return Eigen::Vector3d(val, 0, 0);
    };
    const BSplineNet net = spline_of(f, 3, 3, K, K);
    sols.col(k) = net.points().col(0);
    EXPECT_LT(bspline_pde_equation_residual(net, op), 1e-12) << k;
  }
  EXPECT_EQ(rank_of(sols), 7);
  EXPECT_LT((A * sols).cwiseAbs().maxCoeff(), 1e-10 * sols.cwiseAbs().maxCoeff());
}

TEST(BSplinePde, Example1PaperNetIsNotASolutionButTheSolverFindsOne) {
  const std::vector<double> K = uniform(8);
  const EnergySpec op = EnergySpec::second_order(1, -2, 1);
  Eigen::MatrixX3d P(16, 3);
  P << 1, 1, 1, 1, 2, -8, 1, 3, 8, 1, 4, 1,                     // P_0j (prescribed)
      2, 1, 8, 2, 2, -5. / 9, 2, 3, 119. / 9, 2, 4, 4. / 3,     // P_1j
      3, 1, -8, 3, 2, -121. / 9, 3, 3, 7. / 9, 3, 4, -40. / 3,  // P_2j
      4, 1, 1, 4, 2, 4. / 3, 4, 3, 56. / 3, 4, 4, 5;            // P_3j
  const BSplineNet paper(3, 3, K, K, P);
  EXPECT_GT(bspline_pde_equation_residual(paper, op), 1e-3);  // docs/errata.md: the listed net fails the PDE
  const BSplinePdeResult r = solve_bspline_pde(paper, op, std::vector<int>{0, 1, 2, 3});
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.rank, 9);
  EXPECT_EQ(r.free_parameters, 12 - r.rank_free);
  EXPECT_GT(r.free_parameters, 0);
  EXPECT_TRUE(r.minimum_energy_member);
  EXPECT_LT(bspline_pde_equation_residual(r.net, op), 1e-12);
  EXPECT_LT(bspline_pde_residual(r.net, op, 20), 1e-12);
  EXPECT_EQ(r.net.points().topRows(4), P.topRows(4));
}

TEST(BSplinePde, Example2EquationsHaveRank16) {
  // Sun–Zhu Example 2: quintic, 6 x 6 points, uniform knots 0..11, span [5,6]. 26 equations are
  // printed; their rank is 16 (docs/errata.md), for the biharmonic operator and for (1,2,1,0,0).
  const std::vector<double> K = uniform(12);
  for (const EnergySpec& op : {EnergySpec::biharmonic(), EnergySpec::pde_operator({1, 2, 1, 0, 0})}) {
    EXPECT_EQ(rank_of(bspline_pde_equations(5, 5, K, K, op)), 16) << op.name();
    // The paper's 11 prescribed points P_0j, P_i0 then leave 36 - 11 - 16 = 9 free parameters.
    std::vector<int> fixed;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (i == 0 || j == 0) fixed.push_back(i * 6 + j);
    const BSplineNet data = random_net(5, 5, K, K, 17);
    const BSplinePdeResult r = solve_bspline_pde(data, op, fixed);
    ASSERT_TRUE(r.summary.converged) << r.summary.message;
    EXPECT_EQ(r.rank, 16);
    EXPECT_EQ(r.free_parameters, 9);
    EXPECT_EQ(r.compatibility_conditions, 0);
    EXPECT_TRUE(r.minimum_energy_member);
    EXPECT_LT(bspline_pde_equation_residual(r.net, op), 1e-12);
  }
}

TEST(BSplinePde, SingleSpanRecoversExactPolynomialSolutions) {
  // Clamped single span (a Bézier patch on [0.5,2] x [-1,0]): the boundary ring of an exact
  // solution gives back every control point, for several elliptic operators.
  for (const std::array<double, 5>& c : {std::array<double, 5>{1, 0, 2, 0, 1}, {1, 0.5, 3, -0.4, 2}, {1, 0, 3, 0, 2}}) {
    for (int n : {5, 6}) {
      const std::vector<double> U = clamped(n, {}, 0.5, 2), V = clamped(n, {}, -1, 0);
      const BSplineNet exact = spline_of(fourth_order_solution(c, n), n, n, U, V);
      const EnergySpec op = EnergySpec::pde_operator(c);
      ASSERT_LT(bspline_pde_equation_residual(exact, op), 1e-12);
      const BSplinePdeResult r = solve_bspline_pde(blank_free(exact, exact.free_indices(FixedSet::Boundary)), op);
      ASSERT_TRUE(r.summary.converged) << r.summary.message;
      EXPECT_EQ(r.free_parameters, 0);
      EXPECT_EQ(r.compatibility_conditions, 0);
      EXPECT_FALSE(r.minimum_energy_member);
      EXPECT_LT(max_point_error(r.net, exact), 1e-10) << "n = " << n;
    }
  }
}

TEST(BSplinePde, SingleSpanRanksEqualExactMonomialRanks) {
  // Independent truth: the rank of L on bidegree-(n,n) polynomials from the integer matrix of L on
  // monomials u^a v^b (exact integer entries, FullPivLU), against the span equations. The operator
  // [2,0,1,0,0.5] is elliptic but resonant: its rank drops (n = 5: 12 instead of 16), so a
  // single-span net leaves free parameters AND compatibility conditions.
  auto ff = [](int a, int k) {
    double r = 1;
    for (int i = 0; i < k; ++i) r *= a - i;
    return a < k ? 0.0 : r;
  };
  for (const std::array<double, 5>& c : {std::array<double, 5>{1, 0, 2, 0, 1},
                                         {2, 0, 1, 0, 0.5},
                                         {1, 0.5, 3, -0.4, 2},
                                         {0, 0, 1, 0, 0},
                                         {1, 0, 0, 0, 0}})
    for (int n = 4; n <= 7; ++n) {
      const int N = (n + 1) * (n + 1);
      Eigen::MatrixXd M = Eigen::MatrixXd::Zero(N, N);
      for (int a = 0; a <= n; ++a)
        for (int b = 0; b <= n; ++b)
          for (int t = 0; t < 5; ++t) {
            const int ku = 4 - t, kv = t;
            const double v = c[static_cast<size_t>(t)] * ff(a, ku) * ff(b, kv);
            if (v != 0) M((a - ku) * (n + 1) + b - kv, a * (n + 1) + b) += v;
          }
      const int exact = static_cast<int>(Eigen::FullPivLU<Eigen::MatrixXd>(M).rank());
      const std::vector<double> K = clamped(n, {}, 0.5, 1.75);
      EXPECT_EQ(rank_of(bspline_pde_equations(n, n, K, K, EnergySpec::pde_operator(c))), exact)
          << "[" << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << " " << c[4] << "] n = " << n;
      if (c == std::array<double, 5>{2, 0, 1, 0, 0.5} && n == 5) {
        EXPECT_EQ(exact, 12);
      }
      if (c == std::array<double, 5>{1, 0, 2, 0, 1}) {
        EXPECT_EQ(exact, N - 4 * n);  // 4n biharmonic polynomials
      }
    }
}

TEST(BSplinePde, MultiSpanBiquinticNeedsFourCompatibilityConditions) {
  // 2 x 2 spans, clamped: every solution is one global polynomial (docs/errata.md), so the 24 boundary
  // points must meet 4 conditions (no jump of the 5th derivative of the edge curves at 0.5).
  const std::vector<double> U = clamped(5, {0.5}), V = clamped(5, {0.5});
  const EnergySpec op = EnergySpec::biharmonic();
  const BSplineNet generic = random_net(5, 5, U, V, 5);
  const BSplinePdeResult bad = solve_bspline_pde(generic, op);
  EXPECT_FALSE(bad.summary.converged);
  EXPECT_NE(bad.summary.message.find("incompatible"), std::string::npos);
  EXPECT_EQ(bad.compatibility_conditions, 4);
  EXPECT_EQ(bad.rank, 29);  // 49 - 20: the solution space is the 20 biharmonic polynomials of bidegree (5,5)
  EXPECT_GT(bad.summary.residual, 1e-6);
  EXPECT_EQ(bad.net.points(), generic.points());  // no least-squares net

  // Compatible data (a biharmonic polynomial): the unique solution is that polynomial.
  const BSplineNet exact = spline_of(fourth_order_solution({1, 0, 2, 0, 1}, 5), 5, 5, U, V);
  const BSplinePdeResult r = solve_bspline_pde(blank_free(exact, exact.free_indices(FixedSet::Boundary)), op);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.free_parameters, 0);
  EXPECT_LT(r.summary.residual, 1e-12);
  EXPECT_LT(max_point_error(r.net, exact), 1e-10);
  EXPECT_LT(bspline_pde_residual(r.net, op), 1e-11);
  EXPECT_GT(bspline_pde_residual(generic, op), 1e-2);

  // A small perturbation of compatible data (1e-5 against points of size 8) is caught by the
  // relative tolerance.
  BSplineNet perturbed = blank_free(exact, exact.free_indices(FixedSet::Boundary));
  perturbed.points()(1, 2) += 1e-5;
  EXPECT_FALSE(solve_bspline_pde(perturbed, op).summary.converged);
}

TEST(BSplinePde, UnclampedUniformMultiSpanRecoversPolynomial) {
  // Uniform knots 0..13 at degree 5: 8 x 8 points, 3 x 3 spans, unclamped (the ring is not the
  // boundary curve) - still the unique solution.
  const std::vector<double> K = uniform(14);
  const std::array<double, 5> c{1, 0.5, 3, -0.4, 2};
  const BSplineNet exact = spline_of(fourth_order_solution(c, 5), 5, 5, K, K);
  const BSplinePdeResult r =
      solve_bspline_pde(blank_free(exact, exact.free_indices(FixedSet::Boundary)), EnergySpec::pde_operator(c));
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.free_parameters, 0);
  EXPECT_LT(max_point_error(r.net, exact), 1e-9);
}

TEST(BSplinePde, SecondOrderFromUBoundaries) {
  // Laplace on one clamped span: unique for odd degree, one compatibility condition for even
  // degree (docs/errata.md, explicit PDE solutions: the harmonic count).
  const EnergySpec lap = EnergySpec::dirichlet();
  const Field harmonic = [](double u, double v) {
    return Eigen::Vector3d(u * u * u - 3 * u * v * v, 3 * u * u * v - v * v * v + u, u * v + 2);
  };
  const std::vector<double> K3 = clamped(3, {});
  const BSplineNet exact = spline_of(harmonic, 3, 3, K3, K3);
  BSplinePdeOptions o;
  o.fixed = FixedSet::UBoundaries;
  const BSplinePdeResult r = solve_bspline_pde(blank_free(exact, exact.free_indices(FixedSet::UBoundaries)), lap, o);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.free_parameters, 0);
  EXPECT_LT(max_point_error(r.net, exact), 1e-11);

  const std::vector<double> K4 = clamped(4, {});
  const BSplinePdeResult even = solve_bspline_pde(random_net(4, 4, K4, K4, 3), lap, o);
  EXPECT_FALSE(even.summary.converged);
  EXPECT_EQ(even.compatibility_conditions, 1);
  // General (a, b, c) with real characteristic roots: solutions (u + lam v)^k.
  const EnergySpec op = EnergySpec::second_order(1, 3, 2);  // 1 + 3 lam + 2 lam^2 = 0: lam = -1, -1/2
  const Field f = [](double u, double v) {
    return Eigen::Vector3d(std::pow(u - v, 3), std::pow(u - 0.5 * v, 3) + u, std::pow(u - v, 2) * 0.3 + v);
  };
  const BSplineNet ex2 = spline_of(f, 3, 3, K3, K3);
  const BSplinePdeResult r2 = solve_bspline_pde(blank_free(ex2, ex2.free_indices(FixedSet::UBoundaries)), op, o);
  ASSERT_TRUE(r2.summary.converged) << r2.summary.message;
  EXPECT_LT(bspline_pde_equation_residual(r2.net, op), 1e-12);
}

TEST(BSplinePde, CoonsOperatorGivesTheCoonsPatchOnMultiSpanNets) {
  // x_uuvv = 0 (Sun–Zhu §5, F_Coons = L_{0,0,1,0,0}) with the boundary ring of clamped knots:
  // any boundary is compatible and the solution is the bilinearly blended Coons patch of the
  // boundary curves (docs/errata.md formula), here on 3 x 2 spans.
  const std::vector<double> U = clamped(3, {0.3, 0.6}), V = clamped(4, {0.45});
  const BSplineNet data = random_net(3, 4, U, V, 44);
  const BSplinePdeResult r = solve_bspline_pde(data, EnergySpec::coons());
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.free_parameters, 0);
  EXPECT_LT(bspline_pde_residual(r.net, EnergySpec::coons()), 1e-6);  // rounding/rounding, floored
  EXPECT_GT(bspline_pde_residual(data, EnergySpec::coons()), 0.5);    // a generic net: ratio ~1
  for (double u : {0.1, 0.35, 0.8})
    for (double v : {0.05, 0.5, 0.9}) {
      const Eigen::Vector3d coons = (1 - u) * data.evaluate(0, v) + u * data.evaluate(1, v) +
                                    (1 - v) * data.evaluate(u, 0) + v * data.evaluate(u, 1) -
                                    ((1 - u) * (1 - v) * data.evaluate(0, 0) + (1 - u) * v * data.evaluate(0, 1) +
                                     u * (1 - v) * data.evaluate(1, 0) + u * v * data.evaluate(1, 1));
      EXPECT_LT((r.net.evaluate(u, v) - coons).norm(), 1e-12);
    }
}

TEST(BSplinePde, CoonsSolutionIsTheCoonsExtremal) {
  // Integration by parts: with clamped knots the free basis functions vanish on the boundary, so a
  // net with x_uuvv = 0 on every span (p, q >= 3) is stationary for 1/2 |x_uv|^2 - the PDE solution
  // and the extremal (solvers/bspline/bspline_extremal) must coincide.
  const BSplineNet data = random_net(4, 3, clamped(4, {0.3, 0.6}), clamped(3, {0.45}), 45);
  const BSplinePdeResult r = solve_bspline_pde(data, EnergySpec::coons());
  const BSplineExtremalResult e = solve_bspline_extremal(data, EnergySpec::coons());
  ASSERT_TRUE(r.summary.converged && e.summary.converged);
  EXPECT_LT((r.net.points() - e.net.points()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(r.energy, e.energy, 1e-12 * e.energy);
}

TEST(BSplinePde, DegenerateOperatorReturnsTheMinimumEnergyMember) {
  // x_uuuu = 0 on a biquintic 2 x 2-span net: x is a cubic in u with spline coefficients in v, so
  // the boundary ring leaves free parameters. Data: such a net (compatible).
  const std::vector<double> U = clamped(5, {0.5}), V = clamped(5, {0.5});
  const Eigen::MatrixXd M = polynomial_to_bspline_matrix(3, 0, 1, 5, U);  // 7 x 4
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> R(-1, 1);
  Eigen::MatrixX3d P(49, 3);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd C(4, 7);
    for (int k = 0; k < 28; ++k) C(k / 7, k % 7) = R(rng);
    const Eigen::MatrixXd S = M * C;
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) P(i * 7 + j, c) = S(i, j);
  }
  const BSplineNet member(5, 5, U, V, P);
  const EnergySpec op = EnergySpec::pde_operator({1, 0, 0, 0, 0});
  ASSERT_LT(bspline_pde_equation_residual(member, op), 1e-12);
  const BSplinePdeResult r = solve_bspline_pde(member, op);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_GT(r.free_parameters, 0);
  EXPECT_TRUE(r.minimum_energy_member);
  EXPECT_LT(bspline_pde_equation_residual(r.net, op), 1e-11);
  EXPECT_LE(r.energy, bspline_energy(member, op) * (1 + 1e-12));
  EXPECT_NEAR(r.energy, bspline_energy(r.net, op), 1e-12 * (1 + r.energy));

  // Independent check: the KKT system  min ½ x^T Q x  s.t.  A x = 0, fixed points given.
  const Eigen::MatrixXd A = bspline_pde_equations(5, 5, U, V, op);
  const Eigen::MatrixXd Q(bspline_gram(5, 5, U, V, op));
  const std::vector<int> fixed = member.fixed_indices(FixedSet::Boundary),
                         free = member.free_indices(FixedSet::Boundary);
  const int nf = static_cast<int>(free.size()), m = static_cast<int>(A.rows());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nf + m, nf + m), rhs = Eigen::MatrixXd::Zero(nf + m, 3);
  for (int a = 0; a < nf; ++a) {
    for (int b = 0; b < nf; ++b) K(a, b) = Q(free[a], free[b]);
    for (int e = 0; e < m; ++e) K(nf + e, a) = K(a, nf + e) = A(e, free[a]);
    for (int idx : fixed) rhs.row(a) -= Q(free[a], idx) * P.row(idx);
  }
  for (int e = 0; e < m; ++e)
    for (int idx : fixed) rhs.row(nf + e) -= A(e, idx) * P.row(idx);
  const Eigen::MatrixXd sol = K.completeOrthogonalDecomposition().solve(rhs);
  double err = 0;
  for (int a = 0; a < nf; ++a) err = std::max(err, (sol.row(a) - r.net.points().row(free[a])).norm());
  EXPECT_LT(err, 1e-8 * (1 + P.cwiseAbs().maxCoeff()));
}

TEST(BSplinePde, PdeResidualFollowsTheFormatsDefinition) {
  // x = (u^2, v^2, 0) under Laplace: |Lx| = |(2,2,0)| = 2 sqrt 2 and sum_k |c_k||d^k x| = 2 + 2,
  // at every point: ratio sqrt(2)/2. With weights (1,0,3): |(2,6,0)| / (2 + 6).
  const std::vector<double> U = clamped(3, {0.4}, -1, 1), V = clamped(2, {0.3, 0.6});
  const BSplineNet net = spline_of([](double u, double v) { return Eigen::Vector3d(u * u, v * v, 0); }, 3, 2, U, V);
  EXPECT_NEAR(bspline_pde_residual(net, EnergySpec::dirichlet(), 7), std::sqrt(2.0) / 2, 1e-12);
  EXPECT_NEAR(bspline_pde_residual(net, EnergySpec::second_order(1, 0, 3), 7), std::sqrt(40.0) / 8, 1e-12);
  const BSplineNet harmonic =
      spline_of([](double u, double v) { return Eigen::Vector3d(u * u - v * v, 2 * u * v, u); }, 3, 2, U, V);
  EXPECT_NEAR(bspline_pde_residual(harmonic, EnergySpec::dirichlet(), 7), 0.0, 1e-12);
}

TEST(BSplinePde, BadInputThrowsTypedErrors) {
  const std::vector<double> K3 = clamped(3, {0.5});
  const BSplineNet cubic = random_net(3, 3, K3, K3, 1);
  EXPECT_THROW(solve_bspline_pde(cubic, EnergySpec::biharmonic()), DegreeError);  // x_uuuu of a cubic is 0
  EXPECT_THROW(solve_bspline_pde(random_net(1, 3, clamped(1, {}), K3, 1), EnergySpec::dirichlet()), DegreeError);
  EXPECT_THROW(solve_bspline_pde(cubic, EnergySpec::second_order(0, 0, 0)), ParameterError);
  BSplinePdeOptions ub;
  ub.fixed = FixedSet::UBoundaries;
  const std::vector<double> K5 = clamped(5, {});
  EXPECT_THROW(solve_bspline_pde(random_net(5, 5, K5, K5, 1), EnergySpec::biharmonic(), ub), UnsupportedProblem);
  BSplinePdeOptions tol;
  tol.consistency_tolerance = -1;
  EXPECT_THROW(solve_bspline_pde(cubic, EnergySpec::dirichlet(), tol), ParameterError);
  tol = {};
  tol.rank_tolerance = 2;
  EXPECT_THROW(solve_bspline_pde(cubic, EnergySpec::dirichlet(), tol), ParameterError);
  EXPECT_THROW(solve_bspline_pde(cubic, EnergySpec::dirichlet(), std::vector<int>{5, 5}), ParameterError);
  EXPECT_THROW(bspline_pde_equations(3, 3, {0, 0, 0, 0, 1, 0.5, 1, 1, 1}, K3, EnergySpec::dirichlet()), ParameterError);
  EXPECT_THROW(bspline_pde_equations(3, 3, {0, 0, 0, 1, 1, 1}, K3, EnergySpec::dirichlet()), SizeError);
  // Too large for the dense solve: refused at once, not run for minutes.
  std::vector<double> interior;
  for (int s = 1; s < 60; ++s) interior.push_back(s / 60.0);
  const BSplineNet big(5, 5, clamped(5, interior), clamped(5, interior), Eigen::MatrixX3d::Zero(65 * 65, 3));
  EXPECT_THROW(solve_bspline_pde(big, EnergySpec::biharmonic()), UnsupportedProblem);
}
